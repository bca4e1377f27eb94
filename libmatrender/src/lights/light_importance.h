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
  return cos_a >= cos_b ? 1.0f : cos_a * cos_b + sin_a * sin_b;  // 1 where a <= b
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
  float cos_s, sin_s;
  // Selects rather than an early return, so that loops over lights vectorise.
  SubtendedCone(float radius, float distance) {
    const bool outside = distance > radius;
    const float sin_outside = radius / distance;
    sin_s = outside ? sin_outside : 1.0f;
    cos_s = outside ? std::sqrt(std::max(0.0f, 1.0f - sin_outside * sin_outside)) : 0.0f;
  }
};

// The bound for a one-sided emitter of `power` (radiance times area, channel mean) within a sphere
// of `radius` about `center`, emitting into the half-space away from unit `back`: 0 where p is
// not in front of it. Written without early returns, so that a loop over emitters (the
// rectangles of rect_lights.h) becomes vector instructions.
inline float one_sided_emitter_importance(const glm::vec3& center, const glm::vec3& back, float radius, float power,
                                          const glm::vec3& p, const ReceivingDirections& receiving) {
  const glm::vec3 to_center = center - p;
  const float distance2 = glm::dot(to_center, to_center);
  const float distance = std::sqrt(distance2);
  const glm::vec3 direction = to_center / distance;
  const SubtendedCone cone(radius, distance);
  // The emitter's cosine is between -back and the way to p, -direction.
  const float emitting = cone_cosine_bound(back, direction, cone.cos_s, cone.sin_s);
  const float receiving_factor = receiving_bound(receiving, direction, cone.cos_s, cone.sin_s);
  const float bound = power * emitting * receiving_factor / std::max(distance2, radius * radius);
  return glm::dot(to_center, back) > 0.0f ? bound : 0.0f;
}

}  // namespace matrender
