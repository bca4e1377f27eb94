#include "matrender/blackbody.h"

#include <algorithm>
#include <cmath>

#include "color/cie_xyz.h"

namespace matrender {
namespace {


// Planck's law (the spectral radiance of a blackbody), up to the constant factor 2 h c^2 that the
// normalisation to unit luminance removes: 1 / (lambda^5 (exp(h c / (lambda k T)) - 1)).
double planck(double wavelength_m, double kelvin) {
  constexpr double kH = 6.62607015e-34;   // J s
  constexpr double kC = 2.99792458e8;     // m/s
  constexpr double kK = 1.380649e-23;     // J/K
  const double l5 = std::pow(wavelength_m, 5.0);
  return 1.0 / (l5 * std::expm1(kH * kC / (wavelength_m * kK * kelvin)));
}

}  // namespace

glm::dvec3 blackbody_color(double kelvin) {
  // XYZ as the sum over the table's wavelengths (the step cancels in the normalisation).
  glm::dvec3 xyz(0.0);
  for (size_t i = 0; i < kCie1931.size(); ++i) {
    const double radiance = planck((kCieFirstWavelengthNm + kCieWavelengthStepNm * static_cast<double>(i)) * 1e-9, kelvin);
    for (int c = 0; c < 3; ++c) xyz[c] += radiance * kCie1931[i][c];
  }
  // Y, the luminance, stays 1.
  return glm::max(xyz_to_linear_rec709(xyz / xyz.y), glm::dvec3(0.0));
}

}  // namespace matrender
