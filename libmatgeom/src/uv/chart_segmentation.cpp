#include "matgeom/uv/chart_segmentation.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "triangle_area.h"

namespace matgeom {
namespace {

constexpr uint32_t kUnassigned = std::numeric_limits<uint32_t>::max();

// Vertex ids merged by exact position: attribute seams split vertices without cutting the surface.
std::vector<uint32_t> weld_by_position(const std::vector<glm::dvec3>& positions) {
  std::map<std::tuple<double, double, double>, uint32_t> first;
  std::vector<uint32_t> welded(positions.size());
  for (size_t v = 0; v < positions.size(); ++v) {
    const auto [it, inserted] =
        first.emplace(std::make_tuple(positions[v].x, positions[v].y, positions[v].z), static_cast<uint32_t>(v));
    welded[v] = it->second;
  }
  return welded;
}

// For each triangle and edge (corner c to c + 1), the triangle across that edge, or kUnassigned
// when the edge is a boundary or shared by more than two triangles.
std::vector<glm::uvec3> edge_neighbours(const std::vector<glm::uvec3>& triangles, const std::vector<uint32_t>& welded) {
  std::map<std::pair<uint32_t, uint32_t>, std::vector<std::pair<uint32_t, int>>> edges;
  for (size_t t = 0; t < triangles.size(); ++t)
    for (int c = 0; c < 3; ++c) {
      const uint32_t a = welded[triangles[t][c]], b = welded[triangles[t][(c + 1) % 3]];
      if (a == b) continue;
      edges[std::minmax(a, b)].emplace_back(static_cast<uint32_t>(t), c);
    }
  std::vector<glm::uvec3> neighbours(triangles.size(), glm::uvec3(kUnassigned));
  for (const auto& [edge, faces] : edges) {
    if (faces.size() != 2) continue;
    neighbours[faces[0].first][faces[0].second] = faces[1].first;
    neighbours[faces[1].first][faces[1].second] = faces[0].first;
  }
  return neighbours;
}

bool within_angle(const glm::dvec3& a, const glm::dvec3& b, double cos_limit) {
  const double la = glm::length(a), lb = glm::length(b);
  if (!(la > 0.0) || !(lb > 0.0)) return true;  // an undefined normal constrains nothing
  return glm::dot(a, b) >= cos_limit * la * lb;
}

}  // namespace

std::vector<uint32_t> segment_charts(const std::vector<glm::dvec3>& positions,
                                     const std::vector<glm::uvec3>& triangles, const ChartOptions& options) {
  for (size_t t = 0; t < triangles.size(); ++t)
    for (int c = 0; c < 3; ++c)
      if (triangles[t][c] >= positions.size())
        throw std::invalid_argument("segment_charts: triangle " + std::to_string(t) + " is out of range");
  const double cos_dihedral = std::cos(glm::radians(options.dihedral_threshold_degrees));
  const double cos_planarity = std::cos(glm::radians(options.planarity_bound_degrees));
  const std::vector<glm::uvec3> neighbours = edge_neighbours(triangles, weld_by_position(positions));
  std::vector<glm::dvec3> normals(triangles.size());
  for (size_t t = 0; t < triangles.size(); ++t) {
    const glm::uvec3& c = triangles[t];
    normals[t] = area_vector(positions[c.x], positions[c.y], positions[c.z]);
  }

  std::vector<uint32_t> chart(triangles.size(), kUnassigned);
  uint32_t chart_count = 0;
  for (size_t seed = 0; seed < triangles.size(); ++seed) {
    if (chart[seed] != kUnassigned) continue;
    const uint32_t id = chart_count++;
    chart[seed] = id;
    glm::dvec3 chart_normal = normals[seed];  // area-weighted sum
    std::deque<uint32_t> frontier = {static_cast<uint32_t>(seed)};
    while (!frontier.empty()) {
      const uint32_t t = frontier.front();
      frontier.pop_front();
      for (int c = 0; c < 3; ++c) {
        const uint32_t n = neighbours[t][c];
        if (n == kUnassigned || chart[n] != kUnassigned) continue;
        if (!within_angle(normals[t], normals[n], cos_dihedral)) continue;
        if (!within_angle(chart_normal, normals[n], cos_planarity)) continue;
        chart[n] = id;
        chart_normal += normals[n];
        frontier.push_back(n);
      }
    }
  }
  return chart;
}

}  // namespace matgeom
