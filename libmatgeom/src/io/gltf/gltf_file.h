#pragma once
// A glTF file as tinygltf loaded it: what every part of the reader needs.
#include <string>

#include <tiny_gltf.h>

namespace matgeom::gltf {

// The model and the path every error message starts with.
struct GltfFile {
  std::string path;
  tinygltf::Model model;
  bool quantized = false;  // KHR_mesh_quantization allows integer positions, normals, tangents
};

}  // namespace matgeom::gltf
