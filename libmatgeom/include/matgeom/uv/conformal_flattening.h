#pragma once
// Least-squares conformal maps (Levy, Petitjean, Ray, Maillot 2002, "Least Squares Conformal
// Maps for Automatic Texture Atlas Generation", SIGGRAPH): the flattening of one chart of the
// UV pass. Plain arrays in and out.
#include <vector>

#include <glm/glm.hpp>

namespace matgeom {

// UV coordinates for every vertex, minimising the discrete conformal energy
// sum_T area_T |du/dx - dv/dy|^2 + |du/dy + dv/dx|^2 over the triangles' own orthonormal
// frames (section 3 of the paper). Each component of triangles connected through edges is
// flattened on its own with two pinned vertices (the pair farthest apart along the component's
// longest bounding-box axis, at their 3-D distance), so the result has roughly the surface's
// scale; a vertex where components touch takes its first component's UV (split such vertices
// for a faithful map). Components must have a boundary (a closed surface must be cut into
// charts first). Triangles with zero area carry no energy; vertices no triangle uses get (0, 0).
// Throws std::invalid_argument for indices out of range and std::runtime_error when a
// component's system is singular.
std::vector<glm::dvec2> flatten_lscm(const std::vector<glm::dvec3>& positions,
                                      const std::vector<glm::uvec3>& triangles);

}  // namespace matgeom
