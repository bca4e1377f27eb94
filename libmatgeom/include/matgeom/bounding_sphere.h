#pragma once
// Minimal enclosing sphere of a point set (Welzl 1991, move-to-front variant, expected O(n)).
#include <vector>

#include <glm/glm.hpp>

namespace matgeom {

struct Sphere {
  glm::dvec3 center{0.0};
  double radius = 0.0;
};

// Exact up to floating-point rounding; deterministic (the points are visited in a fixed
// pseudo-random order). An empty input gives a zero sphere at the origin.
Sphere minimal_enclosing_sphere(const std::vector<glm::dvec3>& points);
Sphere minimal_enclosing_sphere(const std::vector<glm::vec3>& points);

}  // namespace matgeom
