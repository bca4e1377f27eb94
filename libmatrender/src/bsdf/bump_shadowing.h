#pragma once
// Cycles' bump shadowing term for diffuse closures whose normal differs from the smooth normal
// (Blender 3.4, kernel/closure/bsdf.h: bump_shadowing_term, applied in bsdf_eval and
// bsdf_sample to CLOSURE_IS_BSDF_DIFFUSE): Chiang, Li, Burley 2019, "Taming the Shadow
// Terminator", SIGGRAPH Talks. With G = (Ns . wi) / ((N . wi)(Ns . N)) it is 1 for G >= 1, 0 for
// G < 0 and -G^3 + G^2 + G between, so light the bent normal N would let in below the smooth
// surface fades out smoothly.
#include <glm/glm.hpp>

namespace matrender {

// In the local shading frame (N = +Z): smooth_normal is the smooth normal Ns, wi the light.
inline float bump_shadowing_term(const glm::vec3& smooth_normal, const glm::vec3& wi) {
  const float denominator = wi.z * smooth_normal.z;
  const float g = denominator != 0.0f ? glm::dot(smooth_normal, wi) / denominator : 0.0f;
  if (g >= 1.0f) return 1.0f;
  if (!(g >= 0.0f)) return 0.0f;
  const float g2 = g * g;
  return -g2 * g + g2 + g;
}

}  // namespace matrender
