// RMSE, PSNR, SRE and ISSM: metrics of the differences, pooled over the covered pixels and all
// channels, as the closed forms of the paper's appendix (table "Analytic expressions") define
// them on the flattened images X and Y.
#include <cmath>
#include <limits>

#include "matlearn/image_metrics.h"
#include "metrics/image_pair.h"

namespace matlearn {
namespace {

// Over the covered pixels and all channels: sum (Y - X)^2, sum X^2, and how many values.
struct PooledSums {
  double squared_error = 0.0, truth_energy = 0.0;
  size_t values = 0;
};

PooledSums pooled_sums(const matbase::FloatImage& truth, const matbase::FloatImage& prediction, const matbase::Mask& mask) {
  const size_t channels = static_cast<size_t>(truth.channels);
  PooledSums sums;
  for (size_t p = 0; p < truth.pixel_count(); ++p) {
    if (!inside(mask, p)) continue;
    sums.values += channels;
    for (size_t c = 0; c < channels; ++c) {
      const double t = truth.values[p * channels + c];
      const double d = static_cast<double>(prediction.values[p * channels + c]) - t;
      sums.squared_error += d * d;
      sums.truth_energy += t * t;
    }
  }
  return sums;
}

}  // namespace

double rmse(const matbase::FloatImage& truth, const matbase::FloatImage& prediction, double data_range, const matbase::Mask& mask) {
  check_image_pair("RMSE", truth, prediction, mask);
  check_data_range("RMSE", data_range);
  const PooledSums sums = pooled_sums(truth, prediction, mask);
  return std::sqrt(sums.squared_error / static_cast<double>(sums.values)) / data_range;
}

double psnr(const matbase::FloatImage& truth, const matbase::FloatImage& prediction, double data_range, const matbase::Mask& mask) {
  check_image_pair("PSNR", truth, prediction, mask);
  check_data_range("PSNR", data_range);
  const PooledSums sums = pooled_sums(truth, prediction, mask);
  if (sums.squared_error == 0.0) return std::numeric_limits<double>::infinity();
  return 10.0 * std::log10(data_range * data_range * static_cast<double>(sums.values) / sums.squared_error);
}

double sre(const matbase::FloatImage& truth, const matbase::FloatImage& prediction, const matbase::Mask& mask) {
  check_image_pair("SRE", truth, prediction, mask);
  const PooledSums sums = pooled_sums(truth, prediction, mask);
  if (sums.squared_error == 0.0) return std::numeric_limits<double>::infinity();
  return 10.0 * std::log10(sums.truth_energy / sums.squared_error);
}

double issm(const matbase::FloatImage& truth, const matbase::FloatImage& prediction, const matbase::Mask& mask) {
  check_image_pair("ISSM", truth, prediction, mask);
  const PooledSums sums = pooled_sums(truth, prediction, mask);
  if (sums.squared_error == 0.0) return 1.0;
  return 1.0 / (1.0 + std::sqrt(sums.squared_error / sums.truth_energy));
}

}  // namespace matlearn
