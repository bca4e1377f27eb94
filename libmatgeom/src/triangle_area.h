#pragma once
// The area of a triangle, the one formula every part of libmatgeom uses for it.
#include <glm/glm.hpp>

namespace matgeom {

// Twice the area of triangle (a, b, c), along its counter-clockwise normal; zero for a
// degenerate triangle.
inline glm::dvec3 area_vector(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  return glm::cross(b - a, c - a);
}

inline double triangle_area(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  return 0.5 * glm::length(area_vector(a, b, c));
}

}  // namespace matgeom
