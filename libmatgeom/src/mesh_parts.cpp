#include "matgeom/mesh_parts.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace matgeom {
namespace {

constexpr uint32_t kUnmapped = std::numeric_limits<uint32_t>::max();

uint32_t part_of(const TriangleMesh& mesh, size_t triangle) {
  return mesh.triangle_parts.empty() ? 0u : mesh.triangle_parts[triangle];
}

// Appends source vertex v's attributes to `part`.
void copy_vertex(const TriangleMesh& source, uint32_t v, TriangleMesh& part) {
  part.positions.push_back(source.positions[v]);
  if (!source.normals.empty()) part.normals.push_back(source.normals[v]);
  if (!source.uvs.empty()) part.uvs.push_back(source.uvs[v]);
  if (!source.tangents.empty()) part.tangents.push_back(source.tangents[v]);
  if (!source.colors.empty()) part.colors.push_back(source.colors[v]);
}

// Appends a part's attribute array; `present` says whether the merged mesh has the attribute.
template <class T>
void append_attribute(std::vector<T>& to, const std::vector<T>& from, size_t vertex_count, bool present,
                      const char* name) {
  if (vertex_count > 0 && present == from.empty())
    throw std::invalid_argument(std::string("merge_parts: some parts have ") + name + " and others do not");
  to.insert(to.end(), from.begin(), from.end());
}

// The distinct part ids the triangles use, ascending.
std::vector<uint32_t> used_part_ids(const TriangleMesh& mesh) {
  if (mesh.triangle_parts.empty()) return mesh.triangles.empty() ? std::vector<uint32_t>{} : std::vector<uint32_t>{0};
  std::vector<uint32_t> ids = mesh.triangle_parts;
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

}  // namespace

std::vector<MeshPart> split_parts(const TriangleMesh& mesh) {
  validate_mesh(mesh, "split_parts");
  const std::vector<uint32_t> ids = used_part_ids(mesh);
  std::vector<MeshPart> parts(ids.size());
  for (size_t k = 0; k < ids.size(); ++k) {
    parts[k].id = ids[k];
    if (ids[k] < mesh.part_names.size()) parts[k].name = mesh.part_names[ids[k]];
    parts[k].mesh.part_names = {parts[k].name};
  }
  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    const auto slot = std::lower_bound(ids.begin(), ids.end(), part_of(mesh, t)) - ids.begin();
    parts[static_cast<size_t>(slot)].source_triangles.push_back(static_cast<uint32_t>(t));
  }
  // One vertex table for all parts, cleared after each part at the entries it used: O(V + T).
  std::vector<uint32_t> new_index(mesh.vertex_count(), kUnmapped);
  for (MeshPart& part : parts) {
    for (const uint32_t t : part.source_triangles) {
      glm::uvec3 triangle;
      for (int corner = 0; corner < 3; ++corner) {
        const uint32_t v = mesh.triangles[t][corner];
        if (new_index[v] == kUnmapped) {
          new_index[v] = static_cast<uint32_t>(part.source_vertices.size());
          part.source_vertices.push_back(v);
          copy_vertex(mesh, v, part.mesh);
        }
        triangle[corner] = new_index[v];
      }
      part.mesh.triangles.push_back(triangle);
    }
    for (const uint32_t v : part.source_vertices) new_index[v] = kUnmapped;
  }
  return parts;
}

NamedParts named_parts(const TriangleMesh& mesh, const std::vector<std::string>& names) {
  NamedParts parts;
  parts.named.assign(mesh.part_count(), false);
  for (const std::string& name : names) {
    const auto found = std::find(mesh.part_names.begin(), mesh.part_names.end(), name);
    if (found == mesh.part_names.end()) {
      if (!parts.missing) parts.missing = name;
      continue;
    }
    parts.named[static_cast<size_t>(found - mesh.part_names.begin())] = true;
  }
  return parts;
}

TriangleMesh merge_parts(const std::vector<MeshPart>& parts) {
  TriangleMesh merged;
  if (parts.empty()) return merged;
  const TriangleMesh& first = parts.front().mesh;
  for (size_t k = 0; k < parts.size(); ++k) {
    const TriangleMesh& part = parts[k].mesh;
    validate_mesh(part, "merge_parts: part " + std::to_string(k));
    if (merged.vertex_count() + part.vertex_count() > std::numeric_limits<uint32_t>::max())
      throw std::invalid_argument("merge_parts: more vertices than 32-bit indices can address");
    const uint32_t offset = static_cast<uint32_t>(merged.vertex_count());
    merged.positions.insert(merged.positions.end(), part.positions.begin(), part.positions.end());
    append_attribute(merged.normals, part.normals, part.vertex_count(), !first.normals.empty(), "normals");
    append_attribute(merged.uvs, part.uvs, part.vertex_count(), !first.uvs.empty(), "uvs");
    append_attribute(merged.tangents, part.tangents, part.vertex_count(), !first.tangents.empty(), "tangents");
    append_attribute(merged.colors, part.colors, part.vertex_count(), !first.colors.empty(), "colours");
    for (const glm::uvec3& triangle : part.triangles) {
      merged.triangles.push_back(triangle + glm::uvec3(offset));
      merged.triangle_parts.push_back(static_cast<uint32_t>(k));
    }
    merged.part_names.push_back(parts[k].name);
  }
  return merged;
}

}  // namespace matgeom
