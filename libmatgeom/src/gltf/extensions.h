#pragma once
// The glTF extensions the reader and the writer share by name.

namespace matgeom::gltf {

// Scales emission beyond glTF's [0, 1] emissiveFactor (its member: emissiveStrength).
constexpr const char* kEmissiveStrength = "KHR_materials_emissive_strength";

}  // namespace matgeom::gltf
