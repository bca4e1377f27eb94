#pragma once
// No NaN or Inf may reach a pixel: the test every stage uses on the vectors it passes on.
#include <cmath>

#include <glm/glm.hpp>

namespace matrender {

inline bool is_finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace matrender
