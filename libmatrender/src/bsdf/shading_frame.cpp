#include "bsdf/shading_frame.h"

#include <algorithm>

namespace matrender {

glm::vec3 ensure_valid_reflection(const glm::vec3& ng, const glm::vec3& wo, const glm::vec3& n) {
  const float threshold = std::min(0.9f * glm::dot(ng, wo), 0.01f);
  const glm::vec3 reflected = 2.0f * glm::dot(n, wo) * n - wo;
  if (glm::dot(ng, reflected) >= threshold) return n;

  // 2-D problem in the plane spanned by x (the part of n orthogonal to ng) and ng. A unit normal
  // (nx, nz) there reflects wo to height 2 (nx ix + nz iz) nz - iz; setting that to `threshold`
  // and squaring gives a quadratic in nz^2 with roots (c +- b) / (2a), where
  // a = ix^2 + iz^2, c = a + iz t, b = sqrt(ix^2 (a - t^2)).
  const glm::vec3 in_plane = n - glm::dot(n, ng) * ng;
  const float in_plane_len = glm::length(in_plane);
  if (!(in_plane_len > 1e-7f)) return ng;
  const glm::vec3 x = in_plane / in_plane_len;
  const float ix = glm::dot(wo, x);
  const float iz = glm::dot(wo, ng);
  const float a = ix * ix + iz * iz;
  if (!(a > 0.0f)) return ng;
  const float b = std::sqrt(std::max(0.0f, ix * ix * (a - threshold * threshold)));
  const float c = iz * threshold + a;
  const float nz2_first = 0.5f * (c + b) / a;
  const float nz2_second = 0.5f * (c - b) / a;

  // Squaring admits roots that are not unit normals above the surface or that reflect below
  // the threshold; keep the ones that work and, of two, the one closest to the original normal
  // (the lower reflection).
  auto is_unit_height = [](float nz2) { return nz2 > 1e-5f && nz2 <= 1.0f + 1e-5f; };
  auto reflection_height = [&](float nz2) {
    const float nx = std::sqrt(std::max(0.0f, 1.0f - nz2));
    const float nz = std::sqrt(std::max(0.0f, nz2));
    return 2.0f * (nx * ix + nz * iz) * nz - iz;
  };
  float nz2;
  const bool first_ok = is_unit_height(nz2_first);
  const bool second_ok = is_unit_height(nz2_second);
  if (first_ok && second_ok) {
    const float r_first = reflection_height(nz2_first);
    const float r_second = reflection_height(nz2_second);
    const bool first_above = r_first >= 1e-5f;
    const bool second_above = r_second >= 1e-5f;
    if (first_above && second_above)
      nz2 = r_first < r_second ? nz2_first : nz2_second;
    else
      nz2 = r_first > r_second ? nz2_first : nz2_second;
  } else if (first_ok || second_ok) {
    nz2 = first_ok ? nz2_first : nz2_second;
  } else {
    return ng;
  }
  const float nx = std::sqrt(std::max(0.0f, 1.0f - nz2));
  const float nz = std::sqrt(std::max(0.0f, nz2));
  return glm::normalize(nx * x + nz * ng);
}

}  // namespace matrender
