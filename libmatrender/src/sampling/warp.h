#pragma once
// Warps from the unit square to directions and points. Equations cite pbrt-v4 (Pharr, Jakob,
// Humphreys 2023), section 13.6 / A.5.
#include <cmath>

#include <glm/glm.hpp>

#include "matbase/pi.h"

namespace matrender {

constexpr float kPi = matbase::kPiAs<float>;
constexpr float kInvPi = 0.31830988618379067154f;

// Shirley-Chiu concentric map of [0,1)^2 onto the unit disk (pbrt-v4 eq. A.5.1): area-preserving
// with low distortion, so stratified samples stay stratified.
inline glm::vec2 sample_uniform_disk_concentric(glm::vec2 u) {
  const glm::vec2 offset = 2.0f * u - glm::vec2(1.0f);
  if (offset.x == 0.0f && offset.y == 0.0f) return glm::vec2(0.0f);
  float r, theta;
  if (std::abs(offset.x) > std::abs(offset.y)) {
    r = offset.x;
    theta = (kPi / 4.0f) * (offset.y / offset.x);
  } else {
    r = offset.y;
    theta = (kPi / 2.0f) - (kPi / 4.0f) * (offset.x / offset.y);
  }
  return r * glm::vec2(std::cos(theta), std::sin(theta));
}

// Malley's method: project the disk onto the hemisphere (+Z); pdf = cos(theta) / pi.
inline glm::vec3 sample_cosine_hemisphere(glm::vec2 u) {
  const glm::vec2 d = sample_uniform_disk_concentric(u);
  const float z = std::sqrt(std::max(0.0f, 1.0f - d.x * d.x - d.y * d.y));
  return glm::vec3(d.x, d.y, z);
}

inline float cosine_hemisphere_pdf(float cos_theta) { return std::max(cos_theta, 0.0f) * kInvPi; }

// Uniform over the hemisphere (+Z): z = u.x, phi = 2 pi u.y (pbrt-v4 eq. A.5.2 with its two
// variables swapped, as Cycles' sample_uniform_hemisphere has them); pdf = 1 / (2 pi).
inline glm::vec3 sample_uniform_hemisphere(glm::vec2 u) {
  const float z = u.x;
  const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
  const float phi = 2.0f * kPi * u.y;
  return glm::vec3(r * std::cos(phi), r * std::sin(phi), z);
}

constexpr float kUniformHemispherePdf = 0.5f * kInvPi;

// Power heuristic with beta = 2 (Veach 1997, eq. 9.13), one sample from each strategy.
inline float power_heuristic(float pdf_a, float pdf_b) {
  const float a2 = pdf_a * pdf_a;
  const float b2 = pdf_b * pdf_b;
  if (!(a2 + b2 > 0.0f) || std::isinf(a2)) return 1.0f;
  return a2 / (a2 + b2);
}

}  // namespace matrender
