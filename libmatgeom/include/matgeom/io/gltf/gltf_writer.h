#pragma once
// glTF 2.0 writer (.glb binary, or .gltf with buffers and images embedded) built on tinygltf:
// the inverse of read_gltf for what an ObjectAsset holds.
#include <string>

#include "matgeom/object_asset.h"

namespace matgeom {

// One node, one mesh, one primitive per part with material k = asset.materials[k]. Converts
// Blender's +Z up to glTF's +Y up ((x, y, z) -> (x, z, -y)) and v to 1 - v, so read_gltf gives
// the asset back. Images are embedded as PNG; roughness and metallic read from other channels or
// images than glTF's (G and B of one image) are packed into one. IOR, clearcoat, transmission,
// velvet (as sheen) and emission strength go into their KHR_materials_* extensions; specular,
// specular tint and label id have no glTF counterpart and are not written. Writes a temporary
// file and renames it; throws std::invalid_argument for an asset it cannot express (no
// triangles, fewer materials than parts, an image index out of range) and std::runtime_error
// naming the path when the file cannot be written.
void write_gltf(const ObjectAsset& asset, const std::string& path);

}  // namespace matgeom
