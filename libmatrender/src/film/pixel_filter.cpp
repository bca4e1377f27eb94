#include "film/pixel_filter.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "matbase/pi.h"

namespace matrender {

double blackman_harris_weight(double x, double radius) {
  if (std::abs(x) > radius) return 0.0;
  const double a = 2.0 * matbase::kPi * (x / (2.0 * radius) + 0.5);
  return 0.35875 - 0.48829 * std::cos(a) + 0.14128 * std::cos(2.0 * a) - 0.01168 * std::cos(3.0 * a);
}

PixelFilterSampler::PixelFilterSampler(double radius) : radius_(radius) {
  // Tabulate the CDF finely with the trapezoid rule, then invert it at kTableSize + 1 evenly
  // spaced probabilities by linear interpolation between CDF samples.
  constexpr int kCdfSteps = 1 << 16;
  const double dx = 2.0 * radius / kCdfSteps;
  std::vector<double> cdf(kCdfSteps + 1, 0.0);
  for (int i = 1; i <= kCdfSteps; ++i) {
    const double x0 = -radius + (i - 1) * dx;
    cdf[i] = cdf[i - 1] + 0.5 * dx * (blackman_harris_weight(x0, radius) + blackman_harris_weight(x0 + dx, radius));
  }
  const double total = cdf.back();
  for (double& c : cdf) c /= total;

  int step = 0;
  for (int k = 0; k <= kTableSize; ++k) {
    const double p = static_cast<double>(k) / kTableSize;
    while (step < kCdfSteps - 1 && cdf[step + 1] < p) ++step;
    const double span = cdf[step + 1] - cdf[step];
    const double t = span > 0.0 ? std::clamp((p - cdf[step]) / span, 0.0, 1.0) : 0.0;
    inverse_cdf_[k] = static_cast<float>(-radius + (step + t) * dx);
  }
}

const PixelFilterSampler& blackman_harris_sampler() {
  static const PixelFilterSampler sampler;
  return sampler;
}

}  // namespace matrender
