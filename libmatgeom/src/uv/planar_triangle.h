#pragma once
// A 3-D triangle laid flat in its own plane, the frame in which flattening and distortion are
// measured: corner 0 at the origin, corner 1 on +x, corner 2 at y > 0 (counter-clockwise).
#include <cmath>

#include <glm/glm.hpp>

namespace matgeom {

struct PlanarTriangle {
  glm::dvec2 corner[3];
  double area = 0.0;  // 0 for a degenerate triangle, whose corners are then all at the origin
};

inline PlanarTriangle planar_triangle(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2) {
  PlanarTriangle flat{};
  const glm::dvec3 e1 = p1 - p0, e2 = p2 - p0;
  const glm::dvec3 normal = glm::cross(e1, e2);
  const double twice_area = glm::length(normal), e1_length = glm::length(e1);
  if (!(twice_area > 0.0) || !(e1_length > 0.0) || !std::isfinite(twice_area)) return flat;
  const glm::dvec3 x_axis = e1 / e1_length;
  const glm::dvec3 y_axis = glm::cross(normal / twice_area, x_axis);
  flat.corner[1] = glm::dvec2(e1_length, 0.0);
  flat.corner[2] = glm::dvec2(glm::dot(e2, x_axis), glm::dot(e2, y_axis));
  flat.area = 0.5 * twice_area;
  return flat;
}

}  // namespace matgeom
