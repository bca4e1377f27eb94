// FSIM (Zhang, Zhang, Mou, Zhang 2011, "FSIM: A Feature Similarity Index for Image Quality
// Assessment", IEEE TIP 20(8)): phase congruency and gradient magnitude compared pixel by pixel,
// weighted by the larger phase congruency. Per channel, averaged over channels.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "matlearn/image_metrics.h"
#include "matlearn/paper_compat_metrics.h"
#include "metrics/image_pair.h"
#include "metrics/phase_congruency.h"

namespace matlearn {
namespace {

std::vector<double> channel_of(const matbase::FloatImage& image, int c) {
  std::vector<double> values(image.pixel_count());
  for (size_t p = 0; p < values.size(); ++p)
    values[p] = image.values[p * static_cast<size_t>(image.channels) + static_cast<size_t>(c)];
  return values;
}

// (2 a b + t) / (a^2 + b^2 + t), eqs. 4 and 5 of the FSIM paper.
double similarity(double a, double b, double t) { return (2.0 * a * b + t) / (a * a + b * b + t); }

// The FSIM sum of one channel: sum S_PC S_G PC_m / sum PC_m over the covered pixels (eq. 7).
double fsim_of_channel(const std::vector<double>& pc_x, const std::vector<double>& pc_y,
                       const std::vector<double>& gm_x, const std::vector<double>& gm_y, double t1, double t2,
                       const matbase::Mask& mask) {
  double weighted = 0.0, weights = 0.0;
  for (size_t p = 0; p < pc_x.size(); ++p) {
    if (!inside(mask, p)) continue;
    const double pc_max = std::max(pc_x[p], pc_y[p]);
    weighted += similarity(pc_x[p], pc_y[p], t1) * similarity(gm_x[p], gm_y[p], t2) * pc_max;
    weights += pc_max;
  }
  return weighted / weights;  // NaN where no pixel has any phase congruency
}

// Scharr gradient magnitude with the kernel normalised by 16 (FSIM's reference code), edges
// replicated outward.
std::vector<double> scharr_magnitude(const std::vector<double>& v, int width, int height) {
  const auto at = [&](int x, int y) {
    x = std::clamp(x, 0, width - 1);
    y = std::clamp(y, 0, height - 1);
    return v[static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)];
  };
  std::vector<double> magnitude(v.size());
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const double gx = (3.0 * (at(x + 1, y - 1) - at(x - 1, y - 1)) + 10.0 * (at(x + 1, y) - at(x - 1, y)) +
                         3.0 * (at(x + 1, y + 1) - at(x - 1, y + 1))) / 16.0;
      const double gy = (3.0 * (at(x - 1, y + 1) - at(x - 1, y - 1)) + 10.0 * (at(x, y + 1) - at(x, y - 1)) +
                         3.0 * (at(x + 1, y + 1) - at(x + 1, y - 1))) / 16.0;
      magnitude[static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)] = std::hypot(gx, gy);
    }
  return magnitude;
}

}  // namespace

double fsim(const matbase::FloatImage& truth, const matbase::FloatImage& prediction, double data_range, const matbase::Mask& mask) {
  check_image_pair("FSIM", truth, prediction, mask);
  check_data_range("FSIM", data_range);
  // The reference code's phase congruency: 4 scales, 4 orientations, shortest wavelength 6,
  // scale factor 2, sigma_on_f 0.55; T1 = 0.85 and T2 = 160 for 8-bit values, rescaled to the
  // data range (gradients scale with it, T2 with its square).
  PhaseCongruencySettings settings;
  settings.orientations = 4;
  settings.min_wavelength = 6.0;
  settings.scale_factor = 2.0;
  const double t1 = 0.85, t2 = 160.0 * (data_range / 255.0) * (data_range / 255.0);
  double total = 0.0;
  for (int c = 0; c < truth.channels; ++c) {
    const std::vector<double> x = channel_of(truth, c), y = channel_of(prediction, c);
    const PhaseCongruency pc_x = phase_congruency(x, truth.width, truth.height, settings);
    const PhaseCongruency pc_y = phase_congruency(y, truth.width, truth.height, settings);
    total += fsim_of_channel(pc_x.overall, pc_y.overall, scharr_magnitude(x, truth.width, truth.height),
                             scharr_magnitude(y, truth.width, truth.height), t1, t2, mask);
  }
  return total / truth.channels;
}

namespace paper_compat {
namespace {

// OpenCV's Scharr(dx, dy) into CV_16U (negative derivatives saturate to 0) with its default
// border (reflect-101), then numpy's sqrt(gx ** 2 + gy ** 2) on those uint16 arrays, whose
// squares and sum wrap modulo 2^16.
std::vector<double> wrapped_scharr_magnitude(const std::vector<double>& v, int width, int height) {
  const auto reflect101 = [](int i, int n) { return n == 1 ? 0 : (i < 0 ? -i : (i >= n ? 2 * n - 2 - i : i)); };
  const auto at = [&](int x, int y) {
    return v[static_cast<size_t>(reflect101(y, height)) * static_cast<size_t>(width) +
             static_cast<size_t>(reflect101(x, width))];
  };
  const auto saturate_u16 = [](double d) { return static_cast<uint16_t>(std::clamp(std::lround(d), 0L, 65535L)); };
  std::vector<double> magnitude(v.size());
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const uint16_t gx = saturate_u16(3.0 * (at(x + 1, y - 1) - at(x - 1, y - 1)) + 10.0 * (at(x + 1, y) - at(x - 1, y)) +
                                       3.0 * (at(x + 1, y + 1) - at(x - 1, y + 1)));
      const uint16_t gy = saturate_u16(3.0 * (at(x - 1, y + 1) - at(x - 1, y - 1)) + 10.0 * (at(x, y + 1) - at(x, y - 1)) +
                                       3.0 * (at(x + 1, y + 1) - at(x + 1, y - 1)));
      const uint16_t wrapped = static_cast<uint16_t>(static_cast<uint16_t>(gx * gx) + static_cast<uint16_t>(gy * gy));
      magnitude[static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)] =
          std::sqrt(static_cast<float>(wrapped));  // numpy's sqrt of uint16 is float32
    }
  return magnitude;
}

}  // namespace

double fsim(const Image8& truth, const Image8& prediction) {
  const matbase::FloatImage x = widen(truth), y = widen(prediction);
  check_image_pair("FSIM (paper compat)", x, y, {});
  // phasepack's phasecong as the package calls it: 6 orientations, nscale 4, minWaveLength 6,
  // mult 2, sigmaOnf 0.5978; the six orientations' PC maps summed; T1 = 0.85, T2 = 160.
  PhaseCongruencySettings settings;
  settings.min_wavelength = 6.0;
  settings.scale_factor = 2.0;
  settings.sigma_on_f = 0.5978;
  double total = 0.0;
  for (int c = 0; c < x.channels; ++c) {
    const std::vector<double> a = channel_of(x, c), b = channel_of(y, c);
    std::vector<double> pc_a(a.size(), 0.0), pc_b(b.size(), 0.0);
    for (const std::vector<double>& o : phase_congruency(a, x.width, x.height, settings).per_orientation)
      for (size_t p = 0; p < o.size(); ++p) pc_a[p] += o[p];
    for (const std::vector<double>& o : phase_congruency(b, x.width, x.height, settings).per_orientation)
      for (size_t p = 0; p < o.size(); ++p) pc_b[p] += o[p];
    total += fsim_of_channel(pc_a, pc_b, wrapped_scharr_magnitude(a, x.width, x.height),
                             wrapped_scharr_magnitude(b, x.width, x.height), 0.85, 160.0, {});
  }
  return total / x.channels;
}

}  // namespace paper_compat
}  // namespace matlearn
