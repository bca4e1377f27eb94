#pragma once
// A triangle mesh as plain arrays: the one geometry type every part of matpredict exchanges.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace matgeom {

// World units are metres, +Z up (Blender's frame). Per-vertex arrays are either empty or have
// positions.size() entries; per-triangle arrays are either empty or have triangles.size() entries.
struct TriangleMesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;     // smooth shading normals; empty = flat (geometric) shading
  std::vector<glm::vec2> uvs;         // empty = no texture coordinates
  std::vector<glm::vec4> tangents;    // xyz tangent along +u, w = bitangent sign (MikkTSpace)
  // Linear RGB per vertex (a scan's colours; Blender's colour attribute, decoded from sRGB), each
  // channel finite and >= 0; empty = none. A material reads them only where it says so
  // (MaterialInputs::vertex_colors).
  std::vector<glm::vec3> colors;
  std::vector<glm::uvec3> triangles;  // vertex indices, counter-clockwise seen from outside
  std::vector<uint32_t> triangle_parts;  // part id per triangle; empty = every triangle in part 0
  std::vector<std::string> part_names;   // name of part k at index k (material slot name)

  size_t vertex_count() const { return positions.size(); }
  size_t triangle_count() const { return triangles.size(); }
  uint32_t part_count() const;
};

// Throws std::invalid_argument naming `what` and the problem when array sizes disagree,
// an index is out of range or a position is not finite.
void validate_mesh(const TriangleMesh& mesh, const std::string& what);

// Applies an affine transform to positions, normals (inverse transpose) and tangents.
void transform_mesh(TriangleMesh& mesh, const glm::dmat4& transform);

// Axis-aligned bounds of the positions.
struct Bounds3 {
  glm::dvec3 lower{0.0};
  glm::dvec3 upper{0.0};
};
Bounds3 mesh_bounds(const TriangleMesh& mesh);

// The surface's area: the sum of its triangles' (square metres for a mesh in metres).
double surface_area(const TriangleMesh& mesh);

// Area-weighted centroid of the surface.
glm::dvec3 surface_centroid(const TriangleMesh& mesh);

}  // namespace matgeom
