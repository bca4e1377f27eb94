#pragma once
// No NaN or Inf may reach a pixel: the test every stage uses on the vectors it passes on.
#include <cmath>

#include <glm/glm.hpp>

namespace matrender {

inline bool is_finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

inline bool is_finite(const glm::dmat4& m) {
  for (int column = 0; column < 4; ++column)
    for (int row = 0; row < 4; ++row)
      if (!std::isfinite(m[column][row])) return false;
  return true;
}

}  // namespace matrender
