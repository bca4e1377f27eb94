#pragma once
// The atmosphere of Blender 3.4's Nishita sky (intern/sky, sky_nishita.cpp): single scattering of
// sunlight by air (Rayleigh) and dust (Mie) in a spherical atmosphere, with ozone absorbing,
// after Nishita, Sirai, Tadamura and Nakamae, "Display of the Earth taking into account
// atmospheric scattering" (SIGGRAPH 1993), eq. 4-8, computed at 21 wavelengths and reduced to
// CIE XYZ. Directions are unit vectors with +Z the zenith; the viewer stands `altitude` metres
// above the ground. Densities scale each constituent (Blender's Air, Dust and Ozone, 1 = Earth's).
#include <glm/glm.hpp>

namespace matrender {

struct AtmosphereDensities {
  double air = 1.0;
  double dust = 1.0;
  double ozone = 1.0;
};

// The sky's radiance (XYZ) along `direction`, lit by a sun along `to_sun`: the light scattered
// towards the viewer along the ray, 32 segments to the top of the atmosphere, each lit through
// the optical depth towards the sun (none where the Earth hides it).
glm::dvec3 nishita_sky_xyz(const glm::dvec3& direction, const glm::dvec3& to_sun, double altitude,
                           const AtmosphereDensities& densities);

// The sun's radiance (XYZ) seen along `to_sun`: its irradiance above the atmosphere, dimmed by air
// and dust along the way, spread evenly over a disc of `solid_angle` steradians.
glm::dvec3 nishita_sun_xyz(const glm::dvec3& to_sun, double altitude, const AtmosphereDensities& densities,
                           double solid_angle);

}  // namespace matrender
