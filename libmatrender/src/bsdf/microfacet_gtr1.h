#pragma once
// Berry's distribution, the "generalised Trowbridge-Reitz" with gamma = 1 that the Principled
// BSDF's clearcoat uses (Burley 2012, "Physically Based Shading at Disney", appendix B.2; Cycles
// 3.4's D_GTR1 in kernel/closure/bsdf_microfacet.h). a2 is the square of the distribution's
// alpha; the clearcoat's alpha is clearcoat_roughness^2, so a2 = clearcoat_roughness^4. Local
// frame: +Z is the normal.
#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "sampling/warp.h"

namespace matrender {

// D(m) = (a2 - 1) / (pi ln(a2) (1 + (a2 - 1) cos^2))   (Burley 2012, eq. 4 of B.2), with the
// denominator's 1 + (a2 - 1) cos^2 written sin^2 + a2 cos^2 so that it keeps its digits at small
// a2 near the normal. At a2 = 1 the limit is 1/pi, Cycles' value for alpha >= 1.
inline float gtr1_d(const glm::vec3& m, float a2) {
  if (m.z <= 0.0f) return 0.0f;
  if (a2 >= 1.0f) return kInvPi;
  const float denominator = m.x * m.x + m.y * m.y + a2 * m.z * m.z;
  return (a2 - 1.0f) / (kPi * std::log(a2) * denominator);
}

// A microfacet normal with density D(m) cos(theta_m) (Burley 2012, B.2, eq. 2):
// cos^2 theta = (1 - a2^(1 - u.x)) / (1 - a2). Both cos^2 and sin^2 come from expm1, so that
// neither is the difference of two numbers near 1 (the normal direction at small a2, the horizon
// at u.x near 1).
inline glm::vec3 gtr1_sample_normal(float a2, glm::vec2 u) {
  float cos2, sin2;
  if (a2 >= 1.0f) {
    cos2 = 1.0f - u.x;
    sin2 = u.x;
  } else {
    const float log_a2 = std::log(a2);
    cos2 = -std::expm1((1.0f - u.x) * log_a2) / (1.0f - a2);
    sin2 = a2 * std::expm1(-u.x * log_a2) / (1.0f - a2);
  }
  const float cos_theta = std::sqrt(std::max(0.0f, cos2));
  const float sin_theta = std::sqrt(std::max(0.0f, sin2));
  const float phi = 2.0f * kPi * u.y;
  return glm::normalize(glm::vec3(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta));
}

// pdf of wi reflected about a normal drawn by gtr1_sample_normal: D(m) cos(theta_m) / (4 wo.m)
// (the reflection Jacobian of Walter et al. 2007, eq. 14).
inline float gtr1_reflection_pdf(const glm::vec3& wo, const glm::vec3& m, float a2) {
  const float wo_dot_m = glm::dot(wo, m);
  if (wo_dot_m <= 0.0f) return 0.0f;
  return gtr1_d(m, a2) * m.z / (4.0f * wo_dot_m);
}

}  // namespace matrender
