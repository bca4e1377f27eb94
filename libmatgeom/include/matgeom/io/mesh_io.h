#pragma once
// Object files of every supported format, chosen by extension (case-insensitive):
// .glb/.gltf (gltf_reader.h, gltf_writer.h), .ply (ply_io.h), .obj (obj_io.h).
#include <string>
#include <vector>

#include "matgeom/object_asset.h"

namespace matgeom {

// The extensions read_object and write_object accept, with the dot.
const std::vector<std::string>& object_file_extensions();

// Reads the file with the reader of its format. PLY has no materials: each part gets
// MaterialInputs(part name), Blender's defaults. Throws std::runtime_error starting with the path.
ObjectAsset read_object(const std::string& path);

// Writes the asset in the format of the extension (PLY keeps the mesh and part names only).
// Throws std::invalid_argument for an unknown extension, as the writers do for a bad asset.
void write_object(const ObjectAsset& asset, const std::string& path);

}  // namespace matgeom
