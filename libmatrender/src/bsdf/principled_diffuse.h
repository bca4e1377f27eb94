#pragma once
// Cycles 3.4's principled diffuse lobe with retro-reflection
// (intern/cycles/kernel/closure/bsdf_principled_diffuse.h, PRINCIPLED_DIFFUSE_FULL), and the plain
// Lambertian lobe of the Diffuse BSDF node. Local frame: +Z is the shading normal; wo and wi point
// away from the surface. eval_* return f * cos(theta_i), the integrand of the rendering equation.
#include <cmath>

#include <glm/glm.hpp>

#include "bsdf/lobe_sample.h"
#include "sampling/warp.h"

namespace matrender {

inline float schlick_weight(float cos_theta) {
  const float m = glm::clamp(1.0f - cos_theta, 0.0f, 1.0f);
  const float m2 = m * m;
  return m2 * m2 * m;
}

// f = 1/pi [(1 - FV/2)(1 - FL/2) + RR (FL + FV + FL FV (RR - 1))], RR = roughness (1 + L.V),
// without the base colour (the caller's closure weight carries it).
inline float principled_diffuse_eval_cos(const glm::vec3& wo, const glm::vec3& wi, float roughness) {
  const float cos_l = wi.z;
  const float cos_v = wo.z;
  if (cos_l <= 0.0f || cos_v <= 0.0f) return 0.0f;
  const float fl = schlick_weight(cos_l);
  const float fv = schlick_weight(cos_v);
  const float rr = roughness * (1.0f + glm::dot(wi, wo));
  const float f = (1.0f - 0.5f * fv) * (1.0f - 0.5f * fl) + rr * (fl + fv + fl * fv * (rr - 1.0f));
  return f * cos_l * kInvPi;
}

inline float lambert_eval_cos(const glm::vec3& wo, const glm::vec3& wi) {
  if (wi.z <= 0.0f || wo.z <= 0.0f) return 0.0f;
  return wi.z * kInvPi;
}

// Both diffuse lobes, and the sheen, are sampled cosine-weighted.
inline glm::vec3 diffuse_sample(glm::vec2 u) { return sample_cosine_hemisphere(u); }
inline float diffuse_pdf(const glm::vec3& wo, const glm::vec3& wi) {
  return wo.z > 0.0f ? cosine_hemisphere_pdf(wi.z) : 0.0f;
}
// A cosine-sampled lobe's sample(): nothing from below the surface, nothing in its plane.
inline bool sample_diffuse_lobe(const glm::vec3& wo, glm::vec2 u, LobeSample* out) {
  if (wo.z <= 0.0f) return false;
  out->wi = diffuse_sample(u);
  return out->wi.z > 0.0f;
}

}  // namespace matrender
