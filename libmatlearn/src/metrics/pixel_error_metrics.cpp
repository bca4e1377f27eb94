// RMSE, PSNR and SRE: metrics of the per-pixel differences, pooled per channel.
#include <cmath>
#include <limits>
#include <vector>

#include "matlearn/image_metrics.h"
#include "metrics/image_pair.h"

namespace matlearn {
namespace {

// Per channel over the covered pixels: the sum of squared differences and the sum of the truth.
struct ChannelSums {
  std::vector<double> squared_error, truth;
  size_t pixels = 0;
};

ChannelSums channel_sums(const Image& truth, const Image& prediction, const Mask& mask) {
  const size_t channels = static_cast<size_t>(truth.channels);
  ChannelSums sums;
  sums.squared_error.assign(channels, 0.0);
  sums.truth.assign(channels, 0.0);
  for (size_t p = 0; p < truth.pixel_count(); ++p) {
    if (!inside(mask, p)) continue;
    ++sums.pixels;
    for (size_t c = 0; c < channels; ++c) {
      const double t = truth.values[p * channels + c];
      const double d = static_cast<double>(prediction.values[p * channels + c]) - t;
      sums.squared_error[c] += d * d;
      sums.truth[c] += t;
    }
  }
  return sums;
}

}  // namespace

double rmse(const Image& truth, const Image& prediction, double data_range, const Mask& mask) {
  check_image_pair("RMSE", truth, prediction, mask);
  check_data_range("RMSE", data_range);
  const ChannelSums sums = channel_sums(truth, prediction, mask);
  double total = 0.0;
  for (double squared_error : sums.squared_error) total += std::sqrt(squared_error / static_cast<double>(sums.pixels));
  return total / static_cast<double>(truth.channels) / data_range;
}

double psnr(const Image& truth, const Image& prediction, double data_range, const Mask& mask) {
  check_image_pair("PSNR", truth, prediction, mask);
  check_data_range("PSNR", data_range);
  const ChannelSums sums = channel_sums(truth, prediction, mask);
  double squared_error = 0.0;
  for (double e : sums.squared_error) squared_error += e;
  const double mse = squared_error / static_cast<double>(sums.pixels * static_cast<size_t>(truth.channels));
  if (mse == 0.0) return std::numeric_limits<double>::infinity();
  return 10.0 * std::log10(data_range * data_range / mse);
}

double sre(const Image& truth, const Image& prediction, const Mask& mask) {
  check_image_pair("SRE", truth, prediction, mask);
  const ChannelSums sums = channel_sums(truth, prediction, mask);
  const double n = static_cast<double>(sums.pixels);
  double total_db = 0.0;
  for (size_t c = 0; c < sums.truth.size(); ++c) {
    const double mean = sums.truth[c] / n;
    const double mse = sums.squared_error[c] / n;
    if (mse == 0.0) return std::numeric_limits<double>::infinity();
    total_db += 10.0 * std::log10(mean * mean / mse);
  }
  return total_db / static_cast<double>(sums.truth.size());
}

}  // namespace matlearn
