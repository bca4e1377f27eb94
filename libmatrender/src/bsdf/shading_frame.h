#pragma once
// Orthonormal shading frame and Cycles' shading-normal repair.
#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

namespace matrender {

// Frame with z = n; x, y from Duff et al. 2017 ("Building an Orthonormal Basis, Revisited"),
// continuous everywhere except n.z = -1 exactly, and branch-free apart from the sign.
struct ShadingFrame {
  glm::vec3 x, y, z;

  static ShadingFrame from_normal(const glm::vec3& n) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float b = n.x * n.y * a;
    return {glm::vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x),
            glm::vec3(b, sign + n.y * n.y * a, -n.y), n};
  }
  glm::vec3 to_local(const glm::vec3& v) const { return {glm::dot(v, x), glm::dot(v, y), glm::dot(v, z)}; }
  glm::vec3 to_world(const glm::vec3& v) const { return v.x * x + v.y * y + v.z * z; }
};

// The search of ensure_valid_reflection for a normal that fails its test, given the threshold
// height (shading_frame.cpp).
glm::vec3 bend_for_valid_reflection(const glm::vec3& ng, const glm::vec3& wo, const glm::vec3& n, float threshold);

// Bends the shading normal n so that the view direction wo (toward the viewer, unit) mirrored
// about it stays above the geometric surface ng (facing the viewer): Cycles 3.4's
// ensure_valid_reflection (kernel/closure/bsdf_util.h). The mirrored ray must leave at least as
// high as min(0.9 ng.wo, 0.01); if it does not, the new normal is searched in the plane of ng and
// n by solving for the normal whose reflection of wo has exactly that height, taking the solution
// closest to n.
inline glm::vec3 ensure_valid_reflection(const glm::vec3& ng, const glm::vec3& wo, const glm::vec3& n) {
  const float threshold = std::min(0.9f * glm::dot(ng, wo), 0.01f);
  const glm::vec3 reflected = 2.0f * glm::dot(n, wo) * n - wo;
  if (glm::dot(ng, reflected) >= threshold) return n;  // almost always: no call
  return bend_for_valid_reflection(ng, wo, n, threshold);
}

}  // namespace matrender
