#pragma once
// Object files of every supported format, chosen by extension (case-insensitive):
// .glb/.gltf (gltf_reader.h, gltf_writer.h), .ply (ply_io.h), .obj (obj_io.h).
#include <optional>
#include <string>
#include <vector>

#include "matgeom/object_asset.h"

namespace matgeom {

// The extensions read_object and write_object accept, with the dot.
const std::vector<std::string>& object_file_extensions();

// What every format's reader is asked alike.
struct ObjectReadOptions {
  // Shade the faces the file gives no normals smooth up to this angle in degrees, as Blender's
  // Shade Smooth with Auto Smooth does (MissingNormals in matgeom/shading_normals.h), for scans
  // that carry no normals; none: as the format says (OBJ's "s" statements, flat in glTF and PLY).
  std::optional<double> auto_smooth_deg;
};

// Reads the file with the reader of its format. PLY has no materials: each part gets
// MaterialInputs(part name), Blender's defaults, or, where the file has vertex colours, a base
// colour of 1 times them (MaterialInputs::vertex_colors), with a note. Throws std::runtime_error starting with the path.
ObjectAsset read_object(const std::string& path, const ObjectReadOptions& options = {});

// Writes the asset in the format of the extension (PLY keeps the mesh and part names only).
// Throws std::invalid_argument for an unknown extension, as the writers do for a bad asset.
void write_object(const ObjectAsset& asset, const std::string& path);

}  // namespace matgeom
