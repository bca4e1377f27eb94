#include "matmaterial/texture_transform.h"

#include <algorithm>
#include <cmath>

namespace matmaterial {

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
  m.stretch = static_cast<float>(std::max(std::abs(t.scale.x), std::abs(t.scale.y)));
  return m;
}

}  // namespace matmaterial
