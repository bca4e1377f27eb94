#include "matgeom/uv/conformal_flattening.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include "uv/planar_triangle.h"

namespace matgeom {
namespace {

// The rotated edge vectors g_j = perp(p_{j+2} - p_{j+1}) of a triangle in its own orthonormal
// frame, with which the gradient of a linear function is (1 / 2A) sum_j f_j g_j.
struct TriangleGradient {
  glm::dvec2 g[3];
  double area = 0.0;
};

TriangleGradient triangle_gradient(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2) {
  TriangleGradient result;
  const PlanarTriangle flat = planar_triangle(p0, p1, p2);
  if (!(flat.area > 0.0)) return result;
  for (int j = 0; j < 3; ++j) {
    const glm::dvec2 edge = flat.corner[(j + 2) % 3] - flat.corner[(j + 1) % 3];
    result.g[j] = glm::dvec2(-edge.y, edge.x);
  }
  result.area = flat.area;
  return result;
}

// The two vertices farthest apart along the component's longest bounding-box axis.
std::pair<size_t, size_t> pick_pins(const std::vector<glm::dvec3>& positions, const std::vector<size_t>& vertices) {
  glm::dvec3 lower = positions[vertices[0]], upper = lower;
  for (size_t v : vertices) lower = glm::min(lower, positions[v]), upper = glm::max(upper, positions[v]);
  const glm::dvec3 extent = upper - lower;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
  size_t low = vertices[0], high = vertices[0];
  for (size_t v : vertices) {
    if (positions[v][axis] < positions[low][axis]) low = v;
    if (positions[v][axis] > positions[high][axis]) high = v;
  }
  return {low, high};
}

// Vertices of a degenerate triangle that no triangle with area constrains take the UV of a
// constrained vertex of that triangle (repeatedly, through chains of degenerate triangles).
void place_unconstrained(const std::vector<glm::uvec3>& triangles, const std::vector<size_t>& component_triangles,
                         std::vector<bool>& constrained, std::vector<glm::dvec2>& uvs) {
  for (bool changed = true; changed;) {
    changed = false;
    for (size_t t : component_triangles)
      for (int c = 0; c < 3; ++c) {
        const size_t v = triangles[t][c];
        if (constrained[v]) continue;
        for (int other = 1; other < 3; ++other) {
          const size_t w = triangles[t][(c + other) % 3];
          if (!constrained[w]) continue;
          uvs[v] = uvs[w];
          constrained[v] = changed = true;
          break;
        }
      }
  }
}

// Solves one component: unknowns (u, v) of its free vertices; the Cauchy-Riemann residuals
// of every triangle, weighted by sqrt(area), are the rows of a least-squares system whose
// normal equations are symmetric positive definite once two vertices are pinned.
// `constrained` is all false on entry, as it is left on return (scratch for all components).
void flatten_component(const std::vector<glm::dvec3>& positions, const std::vector<glm::uvec3>& triangles,
                       const std::vector<size_t>& component_triangles, const std::vector<size_t>& vertices,
                       std::vector<bool>& constrained, std::vector<glm::dvec2>& uvs) {
  for (size_t v : vertices) uvs[v] = glm::dvec2(0.0);
  std::vector<TriangleGradient> gradients;
  for (size_t t : component_triangles) {
    const glm::uvec3 tri = triangles[t];
    gradients.push_back(triangle_gradient(positions[tri.x], positions[tri.y], positions[tri.z]));
    if (gradients.back().area > 0.0)
      for (int c = 0; c < 3; ++c) constrained[tri[c]] = true;
  }
  std::vector<size_t> solved;
  for (size_t v : vertices)
    if (constrained[v]) solved.push_back(v);
  if (solved.empty()) return;  // only degenerate triangles: everything at (0, 0)

  const auto [pin_a, pin_b] = pick_pins(positions, solved);
  uvs[pin_a] = glm::dvec2(0.0);
  uvs[pin_b] = glm::dvec2(glm::distance(positions[pin_a], positions[pin_b]), 0.0);

  constexpr long kNotUnknown = -1;
  std::vector<long> unknown(positions.size(), kNotUnknown);
  long free_count = 0;
  for (size_t v : solved)
    if (v != pin_a && v != pin_b) unknown[v] = free_count++;

  if (free_count > 0) {
    std::vector<Eigen::Triplet<double>> entries;
    Eigen::VectorXd pinned_terms = Eigen::VectorXd::Zero(2 * static_cast<long>(component_triangles.size()));
    long row = 0;
    for (size_t k = 0; k < component_triangles.size(); ++k) {
      const TriangleGradient& grad = gradients[k];
      if (!(grad.area > 0.0)) continue;
      const glm::uvec3 tri = triangles[component_triangles[k]];
      const double weight = 1.0 / (2.0 * std::sqrt(grad.area));  // sqrt(A) / (2A)
      for (int j = 0; j < 3; ++j) {
        const size_t v = tri[j];
        const glm::dvec2 g = weight * grad.g[j];
        // r1 = du/dx - dv/dy, r2 = du/dy + dv/dx
        const double r1_u = g.x, r1_v = -g.y, r2_u = g.y, r2_v = g.x;
        if (unknown[v] == kNotUnknown) {  // a pin
          pinned_terms[row] += r1_u * uvs[v].x + r1_v * uvs[v].y;
          pinned_terms[row + 1] += r2_u * uvs[v].x + r2_v * uvs[v].y;
          continue;
        }
        const long u_col = 2 * unknown[v], v_col = u_col + 1;
        entries.emplace_back(row, u_col, r1_u);
        entries.emplace_back(row, v_col, r1_v);
        entries.emplace_back(row + 1, u_col, r2_u);
        entries.emplace_back(row + 1, v_col, r2_v);
      }
      row += 2;
    }
    Eigen::SparseMatrix<double> system(row, 2 * free_count);
    system.setFromTriplets(entries.begin(), entries.end());
    const Eigen::SparseMatrix<double> normal = system.transpose() * system;
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(normal);
    if (solver.info() != Eigen::Success)
      throw std::runtime_error("flatten_lscm: the conformal system of a component with " +
                               std::to_string(vertices.size()) + " vertices is singular");
    const Eigen::VectorXd solution = solver.solve(-(system.transpose() * pinned_terms.head(row)));
    if (solver.info() != Eigen::Success || !solution.allFinite())
      throw std::runtime_error("flatten_lscm: solving the conformal system failed");
    for (size_t v : solved)
      if (unknown[v] != kNotUnknown) uvs[v] = glm::dvec2(solution[2 * unknown[v]], solution[2 * unknown[v] + 1]);
  }
  place_unconstrained(triangles, component_triangles, constrained, uvs);
  for (size_t v : vertices) constrained[v] = false;
}

// Components of triangles connected through shared edges (two triangles touching at a
// vertex only are not connected: a conformal map could rotate one about the other freely).
std::vector<std::vector<size_t>> edge_connected_components(const std::vector<glm::uvec3>& triangles) {
  std::vector<size_t> parent(triangles.size());
  std::iota(parent.begin(), parent.end(), size_t{0});
  const auto root = [&](size_t t) {
    while (parent[t] != t) t = parent[t] = parent[parent[t]];
    return t;
  };
  std::map<std::pair<uint32_t, uint32_t>, size_t> first_triangle_of_edge;
  for (size_t t = 0; t < triangles.size(); ++t)
    for (int c = 0; c < 3; ++c) {
      const uint32_t a = triangles[t][c], b = triangles[t][(c + 1) % 3];
      if (a == b) continue;
      const auto [it, inserted] = first_triangle_of_edge.emplace(std::minmax(a, b), t);
      if (!inserted) parent[root(t)] = root(it->second);
    }
  std::vector<std::vector<size_t>> components;
  std::vector<size_t> slot(triangles.size(), triangles.size());
  for (size_t t = 0; t < triangles.size(); ++t) {
    const size_t r = root(t);
    if (slot[r] == triangles.size()) slot[r] = components.size(), components.emplace_back();
    components[slot[r]].push_back(t);
  }
  return components;
}

}  // namespace

std::vector<glm::dvec2> flatten_lscm(const std::vector<glm::dvec3>& positions,
                                      const std::vector<glm::uvec3>& triangles) {
  for (size_t t = 0; t < triangles.size(); ++t)
    for (int c = 0; c < 3; ++c)
      if (triangles[t][c] >= positions.size())
        throw std::invalid_argument("flatten_lscm: triangle " + std::to_string(t) + " references vertex " +
                                    std::to_string(triangles[t][c]) + " of " + std::to_string(positions.size()));
  std::vector<glm::dvec2> uvs(positions.size(), glm::dvec2(0.0));
  std::vector<bool> placed(positions.size(), false);
  std::vector<bool> in_component(positions.size(), false);
  std::vector<glm::dvec2> component_uvs(positions.size(), glm::dvec2(0.0));
  std::vector<bool> constrained(positions.size(), false);
  for (const std::vector<size_t>& component : edge_connected_components(triangles)) {
    std::vector<size_t> vertices;
    for (size_t t : component)
      for (int c = 0; c < 3; ++c) {
        const size_t v = triangles[t][c];
        if (!in_component[v]) in_component[v] = true, vertices.push_back(v);
      }
    flatten_component(positions, triangles, component, vertices, constrained, component_uvs);
    // A vertex shared by components that touch only there keeps its first component's UV.
    for (size_t v : vertices) {
      in_component[v] = false;
      if (!placed[v]) uvs[v] = component_uvs[v], placed[v] = true;
    }
  }
  return uvs;
}

}  // namespace matgeom
