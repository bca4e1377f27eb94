#pragma once
// Splitting a mesh into its parts (per-face instance ids of a scan, or material slots) as
// compact meshes of their own, and merging parts back into one mesh.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "matgeom/mesh.h"

namespace matgeom {

struct MeshPart {
  uint32_t id = 0;     // the part's index in the source mesh
  std::string name;    // the source's part name (empty if the source had none for this id)
  TriangleMesh mesh;   // the part's triangles and the vertices they use, re-indexed; one part
  std::vector<uint32_t> source_vertices;   // source vertex of each vertex of `mesh`
  std::vector<uint32_t> source_triangles;  // source triangle of each triangle of `mesh`
};

// One MeshPart per part that has triangles, in increasing id order. Within a part, triangles
// keep their source order and vertices are numbered in order of first use, so the result
// depends only on the input. Every attribute array the source has is carried over.
std::vector<MeshPart> split_parts(const TriangleMesh& mesh);

// Which parts of `mesh` `names` names, by part name: a flag per part id, and the first name the
// mesh has no part of (none when every name is found).
struct NamedParts {
  std::vector<bool> named;
  std::optional<std::string> missing;
};
NamedParts named_parts(const TriangleMesh& mesh, const std::vector<std::string>& names);

// Concatenates the parts' meshes: part k of the result is parts[k] (named parts[k].name), its
// vertices and triangles follow those of parts[0..k-1]. Attribute arrays must be present in all
// parts or in none (std::invalid_argument otherwise).
TriangleMesh merge_parts(const std::vector<MeshPart>& parts);

}  // namespace matgeom
