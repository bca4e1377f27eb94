#include "metrics/phase_congruency.h"

#include <algorithm>
#include <cmath>

#include "matbase/pi.h"
#include "metrics/fft2d.h"

namespace matlearn {
namespace {

constexpr double kEpsilon = 1e-4;  // phasecong3's guard against division by zero

// Normalised frequency of FFT index k of n samples, as phasecong3 lays out its grid: in
// [-0.5, 0.5) for even n; odd n is divided by n - 1.
double frequency(int k, int n) {
  const double denominator = n % 2 ? n - 1 : n;
  return (k <= (n - 1) / 2 ? k : k - n) / denominator;
}

double median(std::vector<double> values) {
  const size_t middle = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + static_cast<long>(middle), values.end());
  const double upper = values[middle];
  if (values.size() % 2) return upper;
  return 0.5 * (upper + *std::max_element(values.begin(), values.begin() + static_cast<long>(middle)));
}

}  // namespace

PhaseCongruency phase_congruency(const std::vector<double>& image, int width, int height,
                                 const PhaseCongruencySettings& settings) {
  const size_t n = static_cast<size_t>(width) * static_cast<size_t>(height);
  ComplexGrid image_fft(image.begin(), image.end());
  fft2d_forward(image_fft, width, height);

  // Polar frequency coordinates of every FFT cell (y flipped: rows grow downward).
  std::vector<double> radius(n), sin_theta(n), cos_theta(n);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const size_t i = static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x);
      const double fx = frequency(x, width), fy = frequency(y, height);
      radius[i] = std::sqrt(fx * fx + fy * fy);
      const double theta = std::atan2(-fy, fx);
      sin_theta[i] = std::sin(theta);
      cos_theta[i] = std::cos(theta);
    }

  // Radial log-Gabor filters (eq. 12 of Kovesi's "Phase congruency detects corners and edges"),
  // times a Butterworth low-pass (cut-off 0.45, order 15) that keeps the corners of the spectrum
  // out; none passes the mean.
  const double log_sigma2 = 2.0 * std::log(settings.sigma_on_f) * std::log(settings.sigma_on_f);
  std::vector<std::vector<double>> log_gabor(static_cast<size_t>(settings.scales), std::vector<double>(n));
  for (int s = 0; s < settings.scales; ++s) {
    const double centre = 1.0 / (settings.min_wavelength * std::pow(settings.scale_factor, s));
    for (size_t i = 1; i < n; ++i) {
      const double low_pass = 1.0 / (1.0 + std::pow(radius[i] / 0.45, 30.0));
      const double l = std::log(radius[i] / centre);
      log_gabor[static_cast<size_t>(s)][i] = std::exp(-l * l / log_sigma2) * low_pass;
    }
  }

  PhaseCongruency result;
  result.overall.assign(n, 0.0);
  std::vector<double> total_amplitude(n, 0.0);
  std::vector<ComplexGrid> responses(static_cast<size_t>(settings.scales));
  for (int o = 0; o < settings.orientations; ++o) {
    // Angular window: a raised cosine reaching zero at twice the orientation spacing.
    const double angle = o * matbase::kPi / settings.orientations;
    std::vector<double> spread(n);
    for (size_t i = 0; i < n; ++i) {
      const double ds = sin_theta[i] * std::cos(angle) - cos_theta[i] * std::sin(angle);
      const double dc = cos_theta[i] * std::cos(angle) + sin_theta[i] * std::sin(angle);
      const double dtheta = std::min(std::abs(std::atan2(ds, dc)) * settings.orientations / 2.0, matbase::kPi);
      spread[i] = 0.5 * (std::cos(dtheta) + 1.0);
    }
    std::vector<double> sum_e(n, 0.0), sum_o(n, 0.0), sum_amplitude(n, 0.0), max_amplitude(n, 0.0);
    double tau = 0.0;
    for (int s = 0; s < settings.scales; ++s) {
      ComplexGrid& response = responses[static_cast<size_t>(s)];
      response.resize(n);
      for (size_t i = 0; i < n; ++i) response[i] = image_fft[i] * (log_gabor[static_cast<size_t>(s)][i] * spread[i]);
      fft2d_inverse(response, width, height);
      std::vector<double> amplitude(n);
      for (size_t i = 0; i < n; ++i) {
        amplitude[i] = std::abs(response[i]);
        sum_amplitude[i] += amplitude[i];
        sum_e[i] += response[i].real();
        sum_o[i] += response[i].imag();
        max_amplitude[i] = std::max(max_amplitude[i], amplitude[i]);
      }
      // Noise: the smallest scale's amplitudes are mostly noise, Rayleigh-distributed; their
      // median over sqrt(ln 4) estimates the Rayleigh parameter.
      if (s == 0) tau = median(amplitude) / std::sqrt(std::log(4.0));
    }
    // Expected noise energy over all scales (each scale's noise amplitude shrinks by 1 / mult),
    // its mean and spread for a Rayleigh distribution.
    const double inverse_mult = 1.0 / settings.scale_factor;
    const double total_tau = tau * (1.0 - std::pow(inverse_mult, settings.scales)) / (1.0 - inverse_mult);
    const double threshold = total_tau * std::sqrt(matbase::kPi / 2.0) + settings.noise_k * total_tau * std::sqrt((4.0 - matbase::kPi) / 2.0);

    std::vector<double>& pc = result.per_orientation.emplace_back(n, 0.0);
    for (size_t i = 0; i < n; ++i) {
      const double x_energy = std::sqrt(sum_e[i] * sum_e[i] + sum_o[i] * sum_o[i]) + kEpsilon;
      const double mean_e = sum_e[i] / x_energy, mean_o = sum_o[i] / x_energy;
      double energy = 0.0;
      for (const ComplexGrid& response : responses) {
        const double e = response[i].real(), od = response[i].imag();
        energy += e * mean_e + od * mean_o - std::abs(e * mean_o - od * mean_e);
      }
      energy = std::max(energy - threshold, 0.0);
      const double width_of_spread = (sum_amplitude[i] / (max_amplitude[i] + kEpsilon) - 1.0) / (settings.scales - 1);
      const double weight = 1.0 / (1.0 + std::exp((settings.cut_off - width_of_spread) * settings.spread_gain));
      const double weighted_energy = weight * energy;
      pc[i] = sum_amplitude[i] > 0.0 ? weighted_energy / sum_amplitude[i] : 0.0;
      result.overall[i] += weighted_energy;
      total_amplitude[i] += sum_amplitude[i];
    }
  }
  for (size_t i = 0; i < n; ++i) result.overall[i] = total_amplitude[i] > 0.0 ? result.overall[i] / total_amplitude[i] : 0.0;
  return result;
}

}  // namespace matlearn
