#pragma once
#include <glm/glm.hpp>

namespace matrender {

// The directions a shading point can take light from, as its BSDF's lobes say: the half-space
// above the plane normal to `normal` (the shading normal) when every lobe reflects, since a
// reflecting lobe is zero below it; every direction when a lobe transmits. Lamps wholly outside
// are skipped before any sampling work.
struct ReceivingDirections {
  glm::vec3 normal{0.0f, 0.0f, 1.0f};
  bool every_direction = false;
};

// One next-event sample toward a lamp, seen from a shading point.
struct LightSample {
  glm::vec3 wi{0.0f};        // unit direction from the shading point to the lamp
  float distance = 0.0f;     // to the sampled point (shadow ray length)
  glm::vec3 radiance{0.0f};  // area lamp: emitted radiance; delta lamp: intensity / distance^2
  float pdf = 0.0f;          // solid-angle pdf (area lamp) or 1 (delta lamp), before selection
  bool delta = false;        // from a delta light (light_type.h), set by LightSampler::sample from its type
};

// The one sample of a delta light: toward it along wi, `distance` away (infinite for a direction),
// delivering `radiance` (intensity / distance^2 for a lamp, irradiance for a sun), pdf 1.
inline LightSample delta_light_sample(const glm::vec3& wi, float distance, const glm::vec3& radiance) {
  LightSample s;
  s.wi = wi;
  s.distance = distance;
  s.radiance = radiance;
  s.pdf = 1.0f;
  return s;
}

}  // namespace matrender
