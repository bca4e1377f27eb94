#include "bsdf/shading_frame.h"

#include <algorithm>

namespace matrender {

glm::vec3 bend_for_valid_reflection(const glm::vec3& ng, const glm::vec3& wo, const glm::vec3& n, float threshold) {
  // 2-D problem in the plane spanned by x (the part of n orthogonal to ng) and ng. A unit normal
  // (nx, nz) there reflects wo to height 2 (nx ix + nz iz) nz - iz; setting that to `threshold`
  // and squaring gives a quadratic in nz^2 with roots (c +- b) / (2a), where
  // a = ix^2 + iz^2, c = a + iz t, b = sqrt(ix^2 (a - t^2)). Solved in double: at grazing views
  // nz^2 is within float epsilon of 1 and nx = sqrt(1 - nz^2) would lose every digit.
  const glm::dvec3 ng_d(ng), wo_d(wo), n_d(n);
  const glm::dvec3 in_plane = n_d - glm::dot(n_d, ng_d) * ng_d;
  const double in_plane_len = glm::length(in_plane);
  if (!(in_plane_len > 1e-12)) return ng;
  const glm::dvec3 x = in_plane / in_plane_len;
  const double t = threshold;
  const double ix = glm::dot(wo_d, x);
  const double iz = glm::dot(wo_d, ng_d);
  const double a = ix * ix + iz * iz;
  if (!(a > 0.0)) return ng;
  const double b = std::sqrt(std::max(0.0, ix * ix * (a - t * t)));
  const double c = iz * t + a;
  const double nz2_first = 0.5 * (c + b) / a;
  const double nz2_second = 0.5 * (c - b) / a;

  // Squaring admits roots that are not unit normals above the surface or that reflect below
  // the threshold; keep the ones that work and, of two, the one closest to the original normal
  // (the lower reflection).
  auto is_unit_height = [](double nz2) { return nz2 > 1e-5 && nz2 <= 1.0 + 1e-5; };
  auto reflection_height = [&](double nz2) {
    const double nx = std::sqrt(std::max(0.0, 1.0 - nz2));
    const double nz = std::sqrt(std::max(0.0, nz2));
    return 2.0 * (nx * ix + nz * iz) * nz - iz;
  };
  double nz2;
  const bool first_ok = is_unit_height(nz2_first);
  const bool second_ok = is_unit_height(nz2_second);
  if (first_ok && second_ok) {
    const double r_first = reflection_height(nz2_first);
    const double r_second = reflection_height(nz2_second);
    const bool first_above = r_first >= 1e-5;
    const bool second_above = r_second >= 1e-5;
    if (first_above && second_above)
      nz2 = r_first < r_second ? nz2_first : nz2_second;
    else
      nz2 = r_first > r_second ? nz2_first : nz2_second;
  } else if (first_ok || second_ok) {
    nz2 = first_ok ? nz2_first : nz2_second;
  } else {
    return ng;
  }
  const double nx = std::sqrt(std::max(0.0, 1.0 - nz2));
  const double nz = std::sqrt(std::max(0.0, nz2));
  return glm::vec3(glm::normalize(nx * x + nz * ng_d));
}

}  // namespace matrender
