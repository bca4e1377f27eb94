#pragma once
// How far a rendered image is from a reference, for the benchmarks' error-versus-time figures.
#include <cmath>
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

inline double mean(const std::vector<float>& image) {
  double sum = 0.0;
  for (const float v : image) sum += v;
  return sum / static_cast<double>(image.size());
}

}  // namespace bench
