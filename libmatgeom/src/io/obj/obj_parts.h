#pragma once
// Parts and geometry: the faces tinyobjloader returns become parts (by material slot or by
// group) and a TriangleMesh in Blender's frame with one vertex per distinct v/vt/vn triple.
#include <cstdint>
#include <optional>
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
  std::vector<uint32_t> file_positions;  // the file's position index of each vertex
  std::vector<bool> normal_missing;
  std::vector<bool> smooth;  // per triangle: its face is in a smoothing group ("s" other than off or 0)
};

AssembledMesh assemble_mesh(const ObjFile& file, const PartTable& parts);

// Normals the file does not give, as Blender 3.4's importer shades them (shading_normals.h): a
// face in a smoothing group ("s 1", "s 2", ...; groups only turn smoothing on, as in Blender) is
// smooth across every vertex it shares by position index, vertices split by a UV seam included;
// a face before any "s" or after "s off", "s 0" is flat. Auto Smooth, when given, smooths them
// all up to its angle.
void complete_normals(AssembledMesh& assembled, std::optional<double> auto_smooth_deg);

}  // namespace matgeom::obj
