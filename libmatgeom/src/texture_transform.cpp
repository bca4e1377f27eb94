#include "matgeom/texture_transform.h"

#include <algorithm>
#include <cmath>

namespace matgeom {

float UvAffine::stretch() const {
  // Singular values of a 2 x 2 matrix [a b; c d]: sqrt of the eigenvalues of M^T M, the larger
  // being (s + sqrt(s^2 - 4 det^2)) / 2 with s = a^2 + b^2 + c^2 + d^2.
  const float a = linear[0][0], c = linear[0][1], b = linear[1][0], d = linear[1][1];
  const float s = a * a + b * b + c * c + d * d;
  const float det = a * d - b * c;
  return std::sqrt(0.5f * (s + std::sqrt(std::max(0.0f, s * s - 4.0f * det * det))));
}

UvAffine uv_affine(const TextureTransform& t) {
  // In glTF's UVs (v_g = 1 - v): u' = sx cos r u + sy sin r v_g + ox, v_g' = -sx sin r u + sy cos r v_g + oy.
  // With v_g = 1 - v and v' = 1 - v_g': u' = sx cos r u - sy sin r v + (ox + sy sin r),
  // v' = sx sin r u + sy cos r v + (1 - oy - sy cos r), Blender's Mapping node.
  const double c = std::cos(t.rotation), s = std::sin(t.rotation);
  UvAffine m;
  // glm is column-major: linear[column][row].
  m.linear[0] = glm::vec2(static_cast<float>(t.scale.x * c), static_cast<float>(t.scale.x * s));
  m.linear[1] = glm::vec2(static_cast<float>(-t.scale.y * s), static_cast<float>(t.scale.y * c));
  m.translation = glm::vec2(static_cast<float>(t.offset.x + t.scale.y * s),
                            static_cast<float>(1.0 - t.offset.y - t.scale.y * c));
  return m;
}

}  // namespace matgeom
