#include "sky/nishita_atmosphere.h"

#include <array>
#include <cmath>

#include "color/cie_xyz.h"
#include "matbase/pi.h"

namespace matrender {
namespace {

// The model's Earth (Blender 3.4's constants, SI units).
constexpr double kEarthRadius = 6360e3;
constexpr double kAtmosphereRadius = 6420e3;
constexpr double kRayleighScaleHeight = 8e3;
constexpr double kMieScaleHeight = 1.2e3;
constexpr double kMieScattering = 2e-5;  // m^-1 at sea level, every wavelength
constexpr double kMieExtinctionRatio = 1.11;  // extinction over scattering: dust absorbs a little
constexpr double kMieAnisotropy = 0.76;
constexpr int kViewSegments = 32;

// The 21 wavelengths, 380 to 780 nm every 20 nm, and per wavelength: the sun's spectral
// irradiance above the atmosphere (W m^-2 nm^-1), air's Rayleigh scattering coefficient and
// ozone's absorption coefficient at sea-level-equivalent density (m^-1), the values Blender 3.4's
// Nishita sky uses.
constexpr int kWavelengths = 21;
constexpr double kWavelengthStepNm = 20.0;
constexpr std::array<double, kWavelengths> kSunIrradiance = {
    1.45756829855593, 1.56596305559738, 1.65148449067670, 1.71496242737209, 1.75797983805021, 1.78256407885925,
    1.79095108475839, 1.78541550133411, 1.76815554864307, 1.74122069647250, 1.70647127164944, 1.66556087452740,
    1.61993437242452, 1.57083597368892, 1.51932335059305, 1.46628494965214, 1.41245852740172, 1.35844961970384,
    1.30474913844739, 1.25174963272611, 1.19975998755421};
constexpr std::array<double, kWavelengths> kRayleighScattering = {
    5.424820087636473e-5, 4.418549866505454e-5, 3.635151910165377e-5, 3.017929012024763e-5, 2.526320226989157e-5,
    2.130859310621843e-5, 1.809838025320633e-5, 1.547057129129042e-5, 1.330284977336850e-5, 1.150184784075764e-5,
    9.99557429990163e-6,  8.72799973630707e-6,  7.65513700977967e-6,  6.74217203751443e-6,  5.96134125832052e-6,
    5.29034598065810e-6,  4.71115687557433e-6,  4.20910481110487e-6,  3.77218381260133e-6,  3.39051255477280e-6,
    3.05591531679811e-6};
constexpr std::array<double, kWavelengths> kOzoneAbsorption = {
    3.25126849861e-9, 5.85395365047e-9, 1.977191155085e-8, 7.309568762914e-8, 2.0084561514287e-7,
    4.0383958096161e-7, 6.3551335912363e-7, 9.6707041180970e-7, 1.54797400424410e-6, 2.09038647223331e-6,
    2.46128056164565e-6, 2.73551299461512e-6, 2.15125863128643e-6, 1.59051840791988e-6, 1.12356197979857e-6,
    7.3527551487574e-7, 4.6450130357806e-7, 3.3096079921048e-7, 2.2512612292678e-7, 1.4879129266490e-7,
    1.6828623364192e-7};

// Relative densities at a height above the ground: air and dust fall off exponentially, ozone is
// a tent between 10 and 40 km peaking at 25 km.
glm::dvec3 densities_at(double height) {
  double ozone = 0.0;
  if (height >= 10e3 && height < 25e3)
    ozone = height / 15e3 - 2.0 / 3.0;
  else if (height >= 25e3 && height < 40e3)
    ozone = 8.0 / 3.0 - height / 15e3;
  return {std::exp(-height / kRayleighScaleHeight), std::exp(-height / kMieScaleHeight), ozone};
}

// Rayleigh's phase function 3 (1 + mu^2) / (16 pi), and Cornette and Shanks' (1992) for dust.
double rayleigh_phase(double mu) { return 3.0 / (16.0 * matbase::kPi) * (1.0 + mu * mu); }
double mie_phase(double mu) {
  const double g = kMieAnisotropy, g2 = g * g;
  return 3.0 * (1.0 - g2) * (1.0 + mu * mu) / (8.0 * matbase::kPi * (2.0 + g2) * std::pow(1.0 + g2 - 2.0 * g * mu, 1.5));
}

// Distance from `origin` along `direction` to the top of the atmosphere (the far root of
// |origin + t direction| = kAtmosphereRadius; the origin is inside).
double distance_to_space(const glm::dvec3& origin, const glm::dvec3& direction) {
  const double b = glm::dot(direction, origin);
  const double c = glm::dot(origin, origin) - kAtmosphereRadius * kAtmosphereRadius;
  return -b + std::sqrt(std::max(b * b - c, 0.0));
}

// Whether a ray going down from `origin` meets the ground (the model's test: any downward ray
// whose line meets the Earth's sphere).
bool meets_ground(const glm::dvec3& origin, const glm::dvec3& direction) {
  if (direction.z >= 0.0) return false;
  const double b = glm::dot(direction, origin);
  return b * b - (glm::dot(origin, origin) - kEarthRadius * kEarthRadius) >= 0.0;
}

// Gauss-Laguerre quadrature of n = 8 nodes (Abramowitz and Stegun 25.4.45): the nodes are the
// roots of the Laguerre polynomial L_8, the weights x / ((n + 1) L_9(x))^2. Optical depth falls
// off about exponentially along a ray, so the rule's e^-x weighting fits it; the rule is
// stretched so that its last node (22.86) stays inside the ray (x / 25), its weights times e^x.
struct Quadrature {
  std::array<double, 8> nodes{}, weights{};
};

// L_n(x) by the three-term recurrence (A&S 22.7.12).
double laguerre(int n, double x) {
  double previous = 1.0, current = 1.0 - x;
  if (n == 0) return previous;
  for (int k = 1; k < n; ++k) {
    const double next = ((2.0 * k + 1.0 - x) * current - k * previous) / (k + 1.0);
    previous = current;
    current = next;
  }
  return current;
}

Quadrature stretched_laguerre_rule() {
  constexpr int n = 8;
  constexpr double kStretch = 25.0;
  Quadrature rule;
  int found = 0;
  // L_8's roots lie in (0, 23): bracket each on a fine grid, then bisect to double precision.
  constexpr double kStep = 1e-3;
  for (double a = kStep; a < 30.0 && found < n; a += kStep) {
    double lo = a, hi = a + kStep;
    if ((laguerre(n, lo) > 0.0) == (laguerre(n, hi) > 0.0)) continue;
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (lo + hi);
      ((laguerre(n, lo) > 0.0) == (laguerre(n, mid) > 0.0) ? lo : hi) = mid;
    }
    const double x = 0.5 * (lo + hi), l = laguerre(n + 1, x);
    rule.nodes[found] = x / kStretch;
    rule.weights[found] = x / ((n + 1.0) * (n + 1.0) * l * l) * std::exp(x) / kStretch;
    ++found;
  }
  return rule;
}

// Optical depth (air, dust, ozone; in metres at sea-level density) from `origin` to space.
glm::dvec3 optical_depth_to_space(const glm::dvec3& origin, const glm::dvec3& direction) {
  static const Quadrature rule = stretched_laguerre_rule();
  const double length = distance_to_space(origin, direction);
  glm::dvec3 depth(0.0);
  for (size_t i = 0; i < rule.nodes.size(); ++i) {
    const glm::dvec3 p = origin + rule.nodes[i] * length * direction;
    depth += rule.weights[i] * densities_at(glm::length(p) - kEarthRadius);
  }
  return depth * length;
}

glm::dvec3 spectrum_to_xyz(const std::array<double, kWavelengths>& spectrum) {
  glm::dvec3 xyz(0.0);
  // The standard observer every 20 nm from 380 nm: every fourth entry of the 5 nm table.
  for (int i = 0; i < kWavelengths; ++i)
    for (int c = 0; c < 3; ++c) xyz[c] += kCie1931[4 * i][c] * spectrum[i];
  return xyz * kWavelengthStepNm;
}

glm::dvec3 viewer_position(double altitude) { return {0.0, 0.0, kEarthRadius + altitude}; }

}  // namespace

glm::dvec3 nishita_sky_xyz(const glm::dvec3& direction, const glm::dvec3& to_sun, double altitude,
                           const AtmosphereDensities& densities) {
  const glm::dvec3 origin = viewer_position(altitude);
  const double segment_length = distance_to_space(origin, direction) / kViewSegments;
  const glm::dvec3 scale(densities.air, densities.dust, densities.ozone);
  const double mu = glm::dot(direction, to_sun);
  const double phase_air = rayleigh_phase(mu), phase_dust = mie_phase(mu);
  std::array<double, kWavelengths> spectrum{};
  glm::dvec3 depth_to_viewer(0.0);
  // Each segment evaluated at its middle (eq. 4's integral by the midpoint rule).
  for (int s = 0; s < kViewSegments; ++s) {
    const glm::dvec3 p = origin + (s + 0.5) * segment_length * direction;
    const glm::dvec3 density = scale * densities_at(glm::length(p) - kEarthRadius);
    depth_to_viewer += segment_length * density;
    if (meets_ground(p, to_sun)) continue;
    const glm::dvec3 depth = depth_to_viewer + scale * optical_depth_to_space(p, to_sun);
    for (int w = 0; w < kWavelengths; ++w) {
      const double extinction = depth.x * kRayleighScattering[w] + depth.y * kMieExtinctionRatio * kMieScattering +
                                depth.z * kOzoneAbsorption[w];
      const double scattering = density.x * kRayleighScattering[w] * phase_air + density.y * kMieScattering * phase_dust;
      spectrum[w] += std::exp(-extinction) * scattering * kSunIrradiance[w] * segment_length;
    }
  }
  return spectrum_to_xyz(spectrum);
}

glm::dvec3 nishita_sun_xyz(const glm::dvec3& to_sun, double altitude, const AtmosphereDensities& densities,
                           double solid_angle) {
  const glm::dvec3 depth = optical_depth_to_space(viewer_position(altitude), to_sun);
  std::array<double, kWavelengths> spectrum{};
  // Blender's sun is dimmed by air and dust only.
  for (int w = 0; w < kWavelengths; ++w)
    spectrum[w] = kSunIrradiance[w] *
                  std::exp(-(kRayleighScattering[w] * depth.x * densities.air +
                             kMieExtinctionRatio * kMieScattering * depth.y * densities.dust)) /
                  solid_angle;
  return spectrum_to_xyz(spectrum);
}

}  // namespace matrender
