#pragma once
// Parts and geometry: the faces tinyobjloader returns become parts (by material slot or by
// group) and a TriangleMesh in Blender's frame with one vertex per distinct v/vt/vn triple.
#include <cstdint>
#include <string>
#include <vector>

#include "matgeom/mesh.h"
#include "io/obj/obj_loading.h"

namespace matgeom::obj {

// Which part each face of each shape is in, and each part's name and material (an index into
// the file's materials, -1 for none).
struct PartTable {
  std::vector<std::string> names;
  std::vector<int> materials;
  std::vector<std::vector<uint32_t>> face_parts;  // [shape][face]
};

// Parts from material slots: the materials faces use, in the order the .mtl files define them,
// then "default" for faces without one ("usemtl" naming no defined material counts as none).
PartTable parts_by_material(const ObjFile& file);

// Parts from groups: one per distinct "g"/"o" name in file order, unnamed faces in "default";
// a part's material is that of its first face.
PartTable parts_by_group(const ObjFile& file);

// The mesh with a record of where its vertices came from.
struct AssembledMesh {
  TriangleMesh mesh;
  std::vector<int> file_positions;  // the file's position index of each vertex
  std::vector<bool> normal_missing;
};

AssembledMesh assemble_mesh(const ObjFile& file, const PartTable& parts);

// Normals the file does not give are computed (area-weighted) over all faces that share the
// file position, so that vertices split by a UV seam get the same smooth normal.
void complete_normals(AssembledMesh& assembled, const ObjFile& file);

}  // namespace matgeom::obj
