#pragma once
// Wavefront OBJ meshes with their MTL materials: read through tinyobjloader, written by hand.
#include <optional>
#include <string>

#include "matgeom/object_asset.h"

namespace matgeom {

struct ObjReadOptions {
  // Parts from "usemtl" material slots (Blender's default) or from "g"/"o" groups.
  enum class PartsFrom { Material, Group };
  PartsFrom parts_from = PartsFrom::Material;
  // Shade the faces the file gives no normals smooth up to this angle (MissingNormals in
  // matgeom/shading_normals.h); none: as the file's "s" statements say.
  std::optional<double> auto_smooth_deg;
};

// OBJ is +Y up: as Blender's importer does with its default axes, (x, y, z) in the file becomes
// (x, -z, y) in matpredict's +Z up frame, and write_obj converts back.
//
// Reads positions, normals and UVs (split into one vertex per distinct v/vt/vn triple),
// triangulates polygons, shades the faces without "vn" normals flat or smooth as their "s"
// statements say (Blender 3.4's rule: flat unless in a smoothing group), and maps MTL materials to MaterialInputs (Kd, map_Kd, Pr/map_Pr, Pm/map_Pm,
// norm/map_Bump; the conventions are in src/obj/mtl_materials.cpp and mtl_textures.cpp). Faces
// without a material share a part named "default". Every number is checked where the OBJ or MTL
// file writes it (src/obj/obj_text_screening.h, mtl_text_screening.h). Throws std::runtime_error
// starting with the path and naming the problem, with the line for OBJ and MTL statements.
ObjectAsset read_obj(const std::string& path, const ObjReadOptions& options = {});

// Writes the mesh with one "g"/"usemtl" block per part and a .mtl beside it (same stem) with the
// materials' scalar parameters; images referenced by materials are written as PNG beside it.
// Temporary names and renames: a failed write leaves nothing behind.
void write_obj(const ObjectAsset& asset, const std::string& path);

}  // namespace matgeom
