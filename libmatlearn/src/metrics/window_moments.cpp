#include "metrics/window_moments.h"

#include <string>

namespace matlearn {

WindowMoments window_moments(const matbase::FloatImage& truth, const matbase::FloatImage& prediction, int c, int x0, int y0, int size) {
  double sum_x = 0.0, sum_y = 0.0;
  for (int y = y0; y < y0 + size; ++y)
    for (int x = x0; x < x0 + size; ++x) {
      sum_x += truth.at(x, y, c);
      sum_y += prediction.at(x, y, c);
    }
  const double n = static_cast<double>(size) * size;
  WindowMoments m{sum_x / n, sum_y / n, 0.0, 0.0, 0.0};
  for (int y = y0; y < y0 + size; ++y)
    for (int x = x0; x < x0 + size; ++x) {
      const double dx = truth.at(x, y, c) - m.mean_x, dy = prediction.at(x, y, c) - m.mean_y;
      m.var_x += dx * dx;
      m.var_y += dy * dy;
      m.cov_xy += dx * dy;
    }
  m.var_x /= n;
  m.var_y /= n;
  m.cov_xy /= n;
  return m;
}

void check_window_fits(const char* metric, const matbase::FloatImage& image, int size) {
  if (image.width < size || image.height < size)
    throw std::invalid_argument(std::string(metric) + ": the images are " + std::to_string(image.width) + "x" +
                                std::to_string(image.height) + ", smaller than its " + std::to_string(size) + "x" +
                                std::to_string(size) + " window");
}

}  // namespace matlearn
