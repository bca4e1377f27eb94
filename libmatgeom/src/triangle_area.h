#pragma once
// The area of a triangle and the angle at its corners, the one formula of each that every part
// of libmatgeom uses.
#include <cmath>

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

// Interior angle at `apex` between the edges to `p` and `q`; 0 for a zero-length edge.
// atan2 of |cross| and dot stays accurate for angles near 0 and pi, where acos does not.
inline double corner_angle(const glm::dvec3& apex, const glm::dvec3& p, const glm::dvec3& q) {
  const glm::dvec3 e1 = p - apex;
  const glm::dvec3 e2 = q - apex;
  const double sine_term = glm::length(glm::cross(e1, e2));
  const double cosine_term = glm::dot(e1, e2);
  if (sine_term == 0.0 && cosine_term == 0.0) return 0.0;
  return std::atan2(sine_term, cosine_term);
}

}  // namespace matgeom
