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

inline double mean(const std::vector<float>& image) {
  double sum = 0.0;
  for (const float v : image) sum += v;
  return sum / static_cast<double>(image.size());
}

}  // namespace bench
