#include "matgeom/mesh.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "triangle_area.h"

namespace matgeom {
namespace {

bool is_finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

[[noreturn]] void throw_invalid_mesh(const std::string& what, const std::string& problem) {
  throw std::invalid_argument(what + ": " + problem);
}

// Per-vertex and per-triangle arrays are optional: empty, or exactly one entry per element.
void check_optional_array(size_t size, size_t expected, const char* array_name,
                          const char* element_name, const std::string& what) {
  if (size == 0 || size == expected) return;
  std::ostringstream problem;
  problem << "the mesh has " << size << " " << array_name << " for " << expected << " "
          << element_name;
  throw_invalid_mesh(what, problem.str());
}

}  // namespace

uint32_t TriangleMesh::part_count() const {
  uint32_t count = static_cast<uint32_t>(part_names.size());
  for (const uint32_t part : triangle_parts) count = std::max(count, part + 1);
  // Triangles without part ids all belong to part 0.
  if (!triangles.empty()) count = std::max(count, 1u);
  return count;
}

void validate_mesh(const TriangleMesh& mesh, const std::string& what) {
  const size_t vertices = mesh.vertex_count();
  check_optional_array(mesh.normals.size(), vertices, "normals", "vertices", what);
  check_optional_array(mesh.uvs.size(), vertices, "uvs", "vertices", what);
  check_optional_array(mesh.tangents.size(), vertices, "tangents", "vertices", what);
  check_optional_array(mesh.colors.size(), vertices, "colours", "vertices", what);
  check_optional_array(mesh.triangle_parts.size(), mesh.triangle_count(), "part ids", "triangles",
                       what);

  for (size_t v = 0; v < vertices; ++v) {
    if (is_finite(mesh.positions[v])) continue;
    std::ostringstream problem;
    problem << "vertex " << v << " has a non-finite position";
    throw_invalid_mesh(what, problem.str());
  }
  for (size_t v = 0; v < mesh.colors.size(); ++v) {
    const glm::vec3& c = mesh.colors[v];
    if (is_finite(c) && c.x >= 0.0f && c.y >= 0.0f && c.z >= 0.0f) continue;
    std::ostringstream problem;
    problem << "vertex " << v << " has a colour that is negative or not finite";
    throw_invalid_mesh(what, problem.str());
  }

  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    for (int corner = 0; corner < 3; ++corner) {
      const uint32_t index = mesh.triangles[t][corner];
      if (index < vertices) continue;
      std::ostringstream problem;
      problem << "triangle " << t << " references vertex " << index << " but the mesh has "
              << vertices << " vertices";
      throw_invalid_mesh(what, problem.str());
    }
  }
}

void transform_mesh(TriangleMesh& mesh, const glm::dmat4& transform) {
  const glm::dmat3 linear(transform);
  const double determinant = glm::determinant(linear);
  if (!(determinant != 0.0) || !std::isfinite(determinant)) {
    throw std::invalid_argument("transform_mesh: the transform's linear part is singular");
  }
  // Normals are covectors: they map by the inverse transpose so they stay perpendicular to the
  // transformed surface (as pbrt-v4's Transform does for a Normal3).
  const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(linear));

  for (glm::vec3& p : mesh.positions) {
    p = glm::vec3(glm::dvec3(transform * glm::dvec4(glm::dvec3(p), 1.0)));
  }
  for (glm::vec3& n : mesh.normals) {
    const glm::dvec3 mapped = normal_matrix * glm::dvec3(n);
    const double length = glm::length(mapped);
    if (length > 0.0) n = glm::vec3(mapped / length);
  }

  // A mirroring transform (negative determinant) turns the tangent frame left-handed, so the
  // bitangent sign flips, and reverses the triangles' winding, which we restore so that
  // triangles stay counter-clockwise seen from outside.
  const bool mirrors = determinant < 0.0;
  for (glm::vec4& t : mesh.tangents) {
    const glm::dvec3 mapped = linear * glm::dvec3(t);
    const double length = glm::length(mapped);
    const glm::vec3 direction = length > 0.0 ? glm::vec3(mapped / length) : glm::vec3(t);
    t = glm::vec4(direction, mirrors ? -t.w : t.w);
  }
  if (mirrors) {
    for (glm::uvec3& triangle : mesh.triangles) std::swap(triangle[1], triangle[2]);
  }
}

Bounds3 mesh_bounds(const TriangleMesh& mesh) {
  Bounds3 bounds;  // an empty mesh gives the degenerate box at the origin
  if (mesh.positions.empty()) return bounds;
  bounds.lower = bounds.upper = glm::dvec3(mesh.positions.front());
  for (const glm::vec3& p : mesh.positions) {
    bounds.lower = glm::min(bounds.lower, glm::dvec3(p));
    bounds.upper = glm::max(bounds.upper, glm::dvec3(p));
  }
  return bounds;
}

double surface_area(const TriangleMesh& mesh) {
  double area = 0.0;
  for (const glm::uvec3& t : mesh.triangles)
    area += triangle_area(glm::dvec3(mesh.positions[t[0]]), glm::dvec3(mesh.positions[t[1]]), glm::dvec3(mesh.positions[t[2]]));
  return area;
}

glm::dvec3 surface_centroid(const TriangleMesh& mesh) {
  if (mesh.positions.empty()) return glm::dvec3(0.0);
  // Accumulate relative to one vertex so that a small object far from the origin keeps its
  // digits.
  const glm::dvec3 origin(mesh.positions.front());
  glm::dvec3 weighted_sum(0.0);
  double total_area = 0.0;
  for (const glm::uvec3& triangle : mesh.triangles) {
    const glm::dvec3 a = glm::dvec3(mesh.positions[triangle[0]]) - origin;
    const glm::dvec3 b = glm::dvec3(mesh.positions[triangle[1]]) - origin;
    const glm::dvec3 c = glm::dvec3(mesh.positions[triangle[2]]) - origin;
    const double area = triangle_area(a, b, c);
    weighted_sum += area * (a + b + c) / 3.0;
    total_area += area;
  }
  if (total_area > 0.0) return origin + weighted_sum / total_area;

  // No surface (no triangles, or all degenerate): the mean of the vertices is the only centre.
  glm::dvec3 vertex_sum(0.0);
  for (const glm::vec3& p : mesh.positions) vertex_sum += glm::dvec3(p) - origin;
  return origin + vertex_sum / static_cast<double>(mesh.positions.size());
}

}  // namespace matgeom
