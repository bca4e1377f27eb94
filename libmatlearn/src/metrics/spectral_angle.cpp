// SAM: the angle between the channel vectors of the truth and the prediction at each pixel.
#include <cmath>
#include <limits>

#include "matbase/pi.h"
#include "matlearn/image_metrics.h"
#include "metrics/image_pair.h"

namespace matlearn {

double sam_degrees(const matbase::FloatImage& truth, const matbase::FloatImage& prediction, const matbase::Mask& mask) {
  check_image_pair("SAM", truth, prediction, mask);
  const size_t channels = static_cast<size_t>(truth.channels);
  double total = 0.0;
  size_t count = 0;
  for (size_t p = 0; p < truth.pixel_count(); ++p) {
    if (!inside(mask, p)) continue;
    const float* x = &truth.values[p * channels];
    const float* y = &prediction.values[p * channels];
    double dot = 0.0, norm2_x = 0.0, norm2_y = 0.0, wedge2 = 0.0;
    for (size_t i = 0; i < channels; ++i) {
      dot += double(x[i]) * y[i];
      norm2_x += double(x[i]) * x[i];
      norm2_y += double(y[i]) * y[i];
      // |x|^2 |y|^2 sin^2 = sum over i < j of (x_i y_j - x_j y_i)^2 (Lagrange's identity), summed
      // term by term: no cancellation at small angles, where acos of a cosine near 1 loses them.
      for (size_t j = i + 1; j < channels; ++j) {
        const double w = double(x[i]) * y[j] - double(x[j]) * y[i];
        wedge2 += w * w;
      }
    }
    if (norm2_x == 0.0 || norm2_y == 0.0) continue;
    const double sin_scaled = std::sqrt(wedge2);
    total += std::atan2(sin_scaled, dot);
    ++count;
  }
  if (count == 0) return std::numeric_limits<double>::quiet_NaN();
  return total / static_cast<double>(count) * (180.0 / matbase::kPi);
}

}  // namespace matlearn
