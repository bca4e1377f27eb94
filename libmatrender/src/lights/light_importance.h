#pragma once
// How much a light may give a shading point, as the weight light selection picks it by
// (light_sampler.h). Each light's importance() is the irradiance it would give if its emission
// met the point at the most favourable angles its bounding sphere allows: a bound in the manner
// of the light trees of Conty Estevez and Kulla 2018 (section 4.2) and Cycles 3.5, evaluated for
// every light instead of a tree's clusters. It is 0 only where the light cannot light the point
// at all (behind a one-sided lamp, outside a spot's cone, below a reflecting BSDF's plane), so
// the choice changes noise and never the converged image.
#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "lights/light_sample.h"

namespace matrender {

// cos(max(0, a - b)) from the cosines and sines of a and b in [0, pi].
inline float cos_of_clamped_difference(float cos_a, float sin_a, float cos_b, float sin_b) {
  if (cos_a >= cos_b) return 1.0f;  // a <= b
  return cos_a * cos_b + sin_a * sin_b;
}

// The largest cosine between `axis` (unit) and a direction from the shading point into a sphere
// seen in unit direction `to_center` under half-angle s (given by cos s and sin s); 0 when every
// such direction is at or past 90 degrees.
inline float cone_cosine_bound(const glm::vec3& axis, const glm::vec3& to_center, float cos_s, float sin_s) {
  const float cos_a = std::clamp(glm::dot(axis, to_center), -1.0f, 1.0f);
  const float sin_a = std::sqrt(std::max(0.0f, 1.0f - cos_a * cos_a));
  return std::max(0.0f, cos_of_clamped_difference(cos_a, sin_a, cos_s, sin_s));
}

// The receiving side's factor: 1 for a BSDF that transmits, else the bound above for its normal.
inline float receiving_bound(const ReceivingDirections& receiving, const glm::vec3& to_center, float cos_s,
                             float sin_s) {
  return receiving.every_direction ? 1.0f : cone_cosine_bound(receiving.normal, to_center, cos_s, sin_s);
}

// A sphere of `radius` around a point at `distance`, as the cosine and sine of the half-angle it
// subtends; a point inside sees it all around (s = 90 degrees).
struct SubtendedCone {
  float cos_s = 1.0f, sin_s = 0.0f;
  SubtendedCone(float radius, float distance) {
    if (!(distance > radius)) {
      cos_s = 0.0f;
      sin_s = 1.0f;
      return;
    }
    sin_s = radius / distance;
    cos_s = std::sqrt(std::max(0.0f, 1.0f - sin_s * sin_s));
  }
};

}  // namespace matrender
