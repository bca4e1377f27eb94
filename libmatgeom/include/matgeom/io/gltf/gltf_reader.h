#pragma once
// glTF 2.0 (.gltf with external or embedded buffers, and .glb) reader built on tinygltf.
#include <optional>
#include <string>

#include "matgeom/object_asset.h"

namespace matgeom {

struct GltfReadOptions {
  // Shade the primitives without NORMAL smooth up to this angle (MissingNormals in
  // matgeom/shading_normals.h); none: flat, as the glTF 2.0 spec requires.
  std::optional<double> auto_smooth_deg;
};

// Reads every mesh primitive of the default scene (or of all root nodes when there is none),
// applies node transforms, converts glTF's +Y up to Blender's +Z up ((x, y, z) -> (x, -z, y)),
// and makes one part per glTF material (primitives without one share a default slot).
// A primitive without NORMAL is flat (see GltfReadOptions); tangents with compute_tangents() where
// missing and UVs exist. Morph targets are not applied: a mesh whose weights are not all 0 is
// refused. Throws std::runtime_error whose message starts with the path and names the problem
// (unreadable, not glTF, a value of the wrong type or outside glTF's enums, index out of range,
// non-finite vertex, no triangles...).
ObjectAsset read_gltf(const std::string& path, const GltfReadOptions& options = {});

}  // namespace matgeom
