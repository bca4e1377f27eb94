#pragma once
// Isotropic GGX (Trowbridge-Reitz) reflection with separable Smith shadowing, as Cycles 3.4's
// single-scatter GGX (intern/cycles/kernel/closure/bsdf_microfacet.h), sampled from the
// distribution of visible normals (Heitz 2018, "Sampling the GGX Distribution of Visible
// Normals", JCGT 7(4)). Local frame: +Z is the shading normal; directions point away.
#include <cmath>

#include <glm/glm.hpp>

#include "sampling/warp.h"

namespace matrender {

// Below this alpha^2 Cycles treats the lobe as a perfect mirror (bsdf_microfacet.h: the
// "singular" case alpha_x * alpha_y <= 1e-7).
constexpr float kGgxSingularAlpha2 = 1e-7f;

// D(m) = alpha^2 / (pi (cos^2 (alpha^2 - 1) + 1)^2)   (Walter et al. 2007, eq. 33), evaluated as
// alpha^2 / (pi (sin^2 + alpha^2 cos^2)^2) with sin^2 = m.x^2 + m.y^2: the textbook form cancels
// 1 - cos^2 in float and is useless once alpha^2 nears float epsilon (roughness 0.02).
inline float ggx_d(const glm::vec3& m, float alpha) {
  if (m.z <= 0.0f) return 0.0f;
  const float a2 = alpha * alpha;
  const float denom = m.x * m.x + m.y * m.y + a2 * m.z * m.z;
  return a2 / (kPi * denom * denom);
}

// Smith G1 = 2 / (1 + sqrt(1 + alpha^2 tan^2 theta))   (Walter et al. 2007, eq. 34), multiplied
// through by cos theta = w.z: 2 w.z / (w.z + sqrt(w.z^2 + alpha^2 (w.x^2 + w.y^2))), which needs
// no tan^2 (useless in float near normal incidence at tiny alpha) and one division.
inline float ggx_g1(const glm::vec3& w, float alpha) {
  if (w.z <= 0.0f) return 0.0f;
  const float a2_sin2 = alpha * alpha * (w.x * w.x + w.y * w.y);
  return 2.0f * w.z / (w.z + std::sqrt(w.z * w.z + a2_sin2));
}

// Visible normal for view direction wo (wo.z > 0), Heitz 2018 listing 1.
inline glm::vec3 ggx_sample_visible_normal(const glm::vec3& wo, float alpha, glm::vec2 u) {
  const glm::vec3 vh = glm::normalize(glm::vec3(alpha * wo.x, alpha * wo.y, wo.z));
  const float len2 = vh.x * vh.x + vh.y * vh.y;
  const glm::vec3 t1 = len2 > 0.0f ? glm::vec3(-vh.y, vh.x, 0.0f) / std::sqrt(len2)
                                   : glm::vec3(1.0f, 0.0f, 0.0f);
  const glm::vec3 t2 = glm::cross(vh, t1);
  const float r = std::sqrt(u.x);
  const float phi = 2.0f * kPi * u.y;
  const float p1 = r * std::cos(phi);
  const float s = 0.5f * (1.0f + vh.z);
  const float p2 = (1.0f - s) * std::sqrt(std::max(0.0f, 1.0f - p1 * p1)) + s * r * std::sin(phi);
  const glm::vec3 nh =
      p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * vh;
  return glm::normalize(glm::vec3(alpha * nh.x, alpha * nh.y, std::max(1e-7f, nh.z)));
}

inline glm::vec3 reflect_about(const glm::vec3& wo, const glm::vec3& m) {
  return 2.0f * glm::dot(wo, m) * m - wo;
}

// wo refracted through the microfacet m (wo.m > 0) into a medium of relative index eta (the far
// side's over wo's side): wi = -wo / eta + (wo.m / eta - cos_t) m, Snell's law in vector form
// (Walter et al. 2007, eq. 40). False at total internal reflection.
inline bool refract_about(const glm::vec3& wo, const glm::vec3& m, float eta, glm::vec3* wi) {
  const float cos_i = glm::dot(wo, m);
  const float inv_eta = 1.0f / eta;
  const float sin2_t = inv_eta * inv_eta * std::max(0.0f, 1.0f - cos_i * cos_i);
  if (sin2_t >= 1.0f) return false;
  const float cos_t = std::sqrt(1.0f - sin2_t);
  *wi = -inv_eta * wo + (inv_eta * cos_i - cos_t) * m;
  return true;
}

// pdf of wi under visible-normal sampling: G1(wo) D(m) / (4 cos_o)   (Heitz 2018, eq. 17 with
// the reflection Jacobian 1 / (4 wo.m)).
inline float ggx_reflection_pdf(const glm::vec3& wo, const glm::vec3& wi, float alpha) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
  const glm::vec3 m = glm::normalize(wo + wi);
  return ggx_g1(wo, alpha) * ggx_d(m, alpha) / (4.0f * wo.z);
}

}  // namespace matrender
