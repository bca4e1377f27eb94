#include "matlearn/paper_compat_metrics.h"

#include <algorithm>
#include <cmath>

#include "matbase/pi.h"
#include "matlearn/image_metrics.h"
#include "metrics/image_pair.h"
#include "metrics/window_moments.h"

namespace matlearn::paper_compat {

matbase::FloatImage widen(const Image8& image) {
  matbase::FloatImage wide;
  wide.width = image.width;
  wide.height = image.height;
  wide.channels = image.channels;
  wide.values.assign(image.values.begin(), image.values.end());
  return wide;
}

Image8 quantize_8bit(const matbase::FloatImage& image) {
  Image8 narrow;
  narrow.width = image.width;
  narrow.height = image.height;
  narrow.channels = image.channels;
  narrow.values.reserve(image.values.size());
  for (float v : image.values) {
    const float scaled = std::isnan(v) ? 0.0f : std::clamp(v, 0.0f, 1.0f) * 255.0f;
    narrow.values.push_back(static_cast<uint8_t>(std::lround(scaled)));
  }
  return narrow;
}

double rmse(const Image8& truth, const Image8& prediction) {
  const matbase::FloatImage x = widen(truth), y = widen(prediction);
  check_image_pair("RMSE (paper compat)", x, y, {});
  const size_t channels = static_cast<size_t>(x.channels);
  double total = 0.0;
  for (size_t c = 0; c < channels; ++c) {
    double squared_error = 0.0;
    for (size_t p = 0; p < x.pixel_count(); ++p) {
      const double d = (double(x.values[p * channels + c]) - y.values[p * channels + c]) / kMaxP;
      squared_error += d * d;
    }
    total += std::sqrt(squared_error / static_cast<double>(x.pixel_count()));
  }
  return total / static_cast<double>(channels);
}

// The mean of equal-sized bands' MSEs is the pooled MSE.
double psnr(const Image8& truth, const Image8& prediction) { return matlearn::psnr(widen(truth), widen(prediction), kMaxP); }

double ssim(const Image8& truth, const Image8& prediction) { return matlearn::ssim(widen(truth), widen(prediction), kMaxP); }

double sre(const Image8& truth, const Image8& prediction) {
  const matbase::FloatImage x = widen(truth), y = widen(prediction);
  check_image_pair("SRE (paper compat)", x, y, {});
  const size_t channels = static_cast<size_t>(x.channels);
  const double n = static_cast<double>(x.pixel_count());
  double ratio_sum = 0.0;
  for (size_t c = 0; c < channels; ++c) {
    double sum = 0.0, squared_error = 0.0;
    for (size_t p = 0; p < x.pixel_count(); ++p) {
      const double t = x.values[p * channels + c], d = t - y.values[p * channels + c];
      sum += t;
      squared_error += d * d;
    }
    const double mean = sum / n;
    ratio_sum += mean * mean / (std::sqrt(squared_error) / n);
  }
  return 10.0 * std::log10(ratio_sum / static_cast<double>(channels));
}

double uiq(const Image8& truth, const Image8& prediction) {
  const matbase::FloatImage x = widen(truth), y = widen(prediction);
  check_image_pair("UIQ (paper compat)", x, y, {});
  constexpr int kWindow = 8;
  check_window_fits("UIQ (paper compat)", x, kWindow);
  return average_over_windows(x, y, {}, kWindow, kWindow / 2, [](const WindowMoments& m) {
    const double denominator = (m.var_x + m.var_y) * (m.mean_x * m.mean_x + m.mean_y * m.mean_y);
    // The numerator vanishes with the denominator: 0 / 0, which nan_to_num makes 0.
    return denominator > 0.0 ? 4.0 * m.cov_xy * m.mean_x * m.mean_y / denominator : 0.0;
  });
}

double issm(const Image8& truth, const Image8& prediction) {
  check_image_pair("ISSM (paper compat)", widen(truth), widen(prediction), {});
  // The package's ISSM multiplies in an edge correlation from Canny(uint8(x / 16), 100, 200).
  // On 8-bit input those values are at most 15, so Sobel's |dx| + |dy| is at most 2 * 4 * 15 =
  // 120, below the high threshold 200: no edge ever starts, both edge maps are all zero, the
  // correlation is 0 / 0 and the whole ratio NaN, which nan_to_num returns as 0.
  return 0.0;
}

double sam_degrees(const Image8& truth, const Image8& prediction) {
  check_image_pair("SAM (paper compat)", widen(truth), widen(prediction), {});
  const size_t channels = static_cast<size_t>(truth.channels);
  const size_t pixels = static_cast<size_t>(truth.width) * static_cast<size_t>(truth.height);
  double total = 0.0;
  for (size_t p = 0; p < pixels; ++p) {
    uint64_t wrapped_dot = 0;
    double norm2_x = 0.0, norm2_y = 0.0;
    for (size_t c = 0; c < channels; ++c) {
      const uint8_t x = truth.values[p * channels + c], y = prediction.values[p * channels + c];
      wrapped_dot += static_cast<uint8_t>(x * y);  // uint8 times uint8 stays uint8 in numpy
      norm2_x += double(x) * x;
      norm2_y += double(y) * y;
    }
    const double denominator = std::sqrt(norm2_x) * std::sqrt(norm2_y);
    if (denominator == 0.0) return 0.0;
    total += std::acos(std::clamp(static_cast<double>(wrapped_dot) / denominator, -1.0, 1.0));
  }
  return total / static_cast<double>(pixels) * (180.0 / matbase::kPi);
}

}  // namespace matlearn::paper_compat
