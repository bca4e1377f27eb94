#pragma once
// Cutting a surface into near-planar charts along sharp edges, the first step of the UV pass.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace matgeom {

struct ChartOptions {
  // An edge whose two faces' normals differ by more than this is a cut (a ridge or a normal
  // discontinuity).
  double dihedral_threshold_degrees = 60.0;
  // A face joins a chart only while its normal stays within this angle of the chart's
  // area-weighted mean normal; below 90 degrees no chart can close on itself.
  double planarity_bound_degrees = 70.0;
};

// Chart id of every triangle, 0 .. chart count - 1, numbered in order of their first triangle.
// Charts grow from the lowest-numbered unassigned triangle across edges shared by exactly two
// triangles (vertices are matched by position, so split normals or UVs do not cut); edges of
// three or more faces are cuts. Zero-area triangles join any neighbouring chart.
std::vector<uint32_t> segment_charts(const std::vector<glm::dvec3>& positions,
                                     const std::vector<glm::uvec3>& triangles, const ChartOptions& options = {});

}  // namespace matgeom
