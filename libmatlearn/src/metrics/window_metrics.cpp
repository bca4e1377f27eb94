// SSIM and UIQ: statistics of square windows moved one pixel at a time. Each window's means,
// variances and covariance are summed directly (in double, the deviations from the window's own
// means), so a flat window gives exactly zero variance, which UIQ's special cases rely on.
#include <stdexcept>
#include <string>

#include "matlearn/image_metrics.h"
#include "metrics/image_pair.h"

namespace matlearn {
namespace {

struct WindowMoments {
  double mean_x, mean_y;
  double var_x, var_y, cov_xy;  // divided by the pixel count (population moments)
};

// Moments of channel c over the size x size window whose top-left pixel is (x0, y0).
WindowMoments window_moments(const Image& truth, const Image& prediction, int c, int x0, int y0, int size) {
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

void check_window_fits(const char* metric, const Image& image, int size) {
  if (image.width < size || image.height < size)
    throw std::invalid_argument(std::string(metric) + ": the images are " + std::to_string(image.width) + "x" +
                                std::to_string(image.height) + ", smaller than its " + std::to_string(size) + "x" +
                                std::to_string(size) + " window");
}

// The mean over channels of `per_window` averaged over the windows whose anchor pixel, at
// offset (anchor, anchor) from the top-left, lies in the mask.
template <class PerWindow>
double average_over_windows(const Image& truth, const Image& prediction, const Mask& mask, int size, int anchor,
                            PerWindow per_window) {
  double total = 0.0;
  size_t count = 0;
  for (int c = 0; c < truth.channels; ++c)
    for (int y0 = 0; y0 + size <= truth.height; ++y0)
      for (int x0 = 0; x0 + size <= truth.width; ++x0) {
        const size_t pixel = static_cast<size_t>(y0 + anchor) * static_cast<size_t>(truth.width) +
                             static_cast<size_t>(x0 + anchor);
        if (!inside(mask, pixel)) continue;
        total += per_window(window_moments(truth, prediction, c, x0, y0, size));
        ++count;
      }
  if (count == 0) throw std::invalid_argument("the mask covers no whole window");
  return total / static_cast<double>(count);
}

}  // namespace

double ssim(const Image& truth, const Image& prediction, double data_range, const Mask& mask) {
  check_image_pair("SSIM", truth, prediction, mask);
  check_data_range("SSIM", data_range);
  constexpr int kWindow = 7;
  check_window_fits("SSIM", truth, kWindow);
  // scikit-image's structural_similarity defaults: K1 = 0.01, K2 = 0.03, and variances with
  // the sample normalisation N / (N - 1).
  const double c1 = (0.01 * data_range) * (0.01 * data_range), c2 = (0.03 * data_range) * (0.03 * data_range);
  constexpr double kSampleNormalisation = (kWindow * kWindow) / (kWindow * kWindow - 1.0);
  return average_over_windows(truth, prediction, mask, kWindow, kWindow / 2, [&](const WindowMoments& m) {
    const double var_x = kSampleNormalisation * m.var_x, var_y = kSampleNormalisation * m.var_y,
                 cov_xy = kSampleNormalisation * m.cov_xy;
    return (2.0 * m.mean_x * m.mean_y + c1) * (2.0 * cov_xy + c2) /
           ((m.mean_x * m.mean_x + m.mean_y * m.mean_y + c1) * (var_x + var_y + c2));
  });
}

double uiq(const Image& truth, const Image& prediction, const Mask& mask) {
  check_image_pair("UIQ", truth, prediction, mask);
  constexpr int kWindow = 8;
  check_window_fits("UIQ", truth, kWindow);
  return average_over_windows(truth, prediction, mask, kWindow, kWindow / 2, [](const WindowMoments& m) {
    // Q = 4 cov mu_x mu_y / ((var_x + var_y)(mu_x^2 + mu_y^2)), Wang and Bovik 2002, eq. 1.
    const double variances = m.var_x + m.var_y;
    const double means = m.mean_x * m.mean_x + m.mean_y * m.mean_y;
    if (variances > 0.0 && means > 0.0) return 4.0 * m.cov_xy * m.mean_x * m.mean_y / (variances * means);
    if (means > 0.0) return 2.0 * m.mean_x * m.mean_y / means;  // flat windows
    return 1.0;  // img_qi.m leaves Q = 1 where it cannot divide
  });
}

}  // namespace matlearn
