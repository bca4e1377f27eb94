#pragma once
// How far a rendered image is from a reference, for the benchmarks' error-versus-time figures.
#include <cmath>
#include <cstdint>
#include <vector>

namespace bench {

// Root of the mean squared difference over every value (pixels times channels).
inline double rmse(const std::vector<float>& image, const std::vector<float>& reference) {
  double sum = 0.0;
  for (size_t i = 0; i < image.size(); ++i) sum += (double(image[i]) - reference[i]) * (double(image[i]) - reference[i]);
  return std::sqrt(sum / static_cast<double>(image.size()));
}

// The same over the pixels both images cover (coverage > 0), of a one-channel map.
inline double covered_rmse(const std::vector<float>& image, const std::vector<float>& reference,
                           const std::vector<float>& coverage, const std::vector<float>& reference_coverage) {
  double sum = 0.0;
  size_t n = 0;
  for (size_t p = 0; p < coverage.size(); ++p) {
    if (coverage[p] <= 0.0f || reference_coverage[p] <= 0.0f) continue;
    sum += (double(image[p]) - reference[p]) * (double(image[p]) - reference[p]);
    ++n;
  }
  return n ? std::sqrt(sum / static_cast<double>(n)) : 0.0;
}

// The RMSE over the pixels `mask` marks (mask[p] > 0), every channel of them, and their mean in
// `reference`: an image error on the object's pixels alone.
inline double masked_rmse(const std::vector<float>& image, const std::vector<float>& reference,
                          const std::vector<int32_t>& mask, int channels) {
  double sum = 0.0;
  size_t n = 0;
  for (size_t p = 0; p < mask.size(); ++p) {
    if (mask[p] <= 0) continue;
    for (int c = 0; c < channels; ++c) {
      const size_t i = p * static_cast<size_t>(channels) + static_cast<size_t>(c);
      sum += (double(image[i]) - reference[i]) * (double(image[i]) - reference[i]);
      ++n;
    }
  }
  return n ? std::sqrt(sum / static_cast<double>(n)) : 0.0;
}
inline double masked_mean(const std::vector<float>& reference, const std::vector<int32_t>& mask, int channels) {
  double sum = 0.0;
  size_t n = 0;
  for (size_t p = 0; p < mask.size(); ++p) {
    if (mask[p] <= 0) continue;
    for (int c = 0; c < channels; ++c) sum += reference[p * static_cast<size_t>(channels) + static_cast<size_t>(c)];
    n += static_cast<size_t>(channels);
  }
  return n ? sum / static_cast<double>(n) : 0.0;
}

inline double mean(const std::vector<float>& image) {
  double sum = 0.0;
  for (const float v : image) sum += v;
  return sum / static_cast<double>(image.size());
}

// Error against time of one way of rendering, point by point.
struct Curve {
  std::vector<double> seconds, error;  // by increasing time
};

// Seconds to reach `target` error, interpolated log-log between the measured points; the first
// point's when it is already there, NaN when the curve never gets there.
inline double seconds_to_reach(const Curve& curve, double target) {
  for (size_t k = 0; k < curve.error.size(); ++k) {
    if (curve.error[k] > target) continue;
    if (k == 0) return curve.seconds[0];
    const double t =
        (std::log(curve.error[k - 1]) - std::log(target)) / (std::log(curve.error[k - 1]) - std::log(curve.error[k]));
    return std::exp(std::log(curve.seconds[k - 1]) + t * (std::log(curve.seconds[k]) - std::log(curve.seconds[k - 1])));
  }
  return std::nan("");
}

}  // namespace bench
