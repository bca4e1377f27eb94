#pragma once
// How far a UV layout is from an isometry of the surface: the per-part report of the UV pass.
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

namespace matgeom {

struct UvDistortion {
  // Angle distortion of each triangle: sigma_max / sigma_min - 1 of the Jacobian of the map
  // from the triangle to its UVs (0 for a conformal map); area-weighted mean and maximum.
  double angle_mean = 0.0;
  double angle_max = 0.0;
  // Stretch of Sander, Snyder, Gortler, Hoppe 2001 ("Texture Mapping Progressive Meshes",
  // eqs. 2-3) for the map from UV to surface, normalised by sqrt(UV area / surface area) so an
  // isometry up to uniform scale gives 1 and anything else more: L2 (root mean square over the
  // surface) and Linf (max).
  double stretch_l2 = 1.0;
  double stretch_linf = 1.0;
  // Triangles whose UV orientation is opposite to the majority's, and those with zero UV area.
  size_t flipped_triangles = 0;
  size_t degenerate_triangles = 0;
};

// Triangles with zero surface area are ignored; zero UV area counts as degenerate and is left
// out of the stretch (which would be infinite).
UvDistortion measure_uv_distortion(const std::vector<glm::dvec3>& positions,
                                   const std::vector<glm::uvec3>& triangles,
                                   const std::vector<glm::dvec2>& uvs);

}  // namespace matgeom
