#pragma once
// The glTF extensions the reader and the writer share by name.

#include <array>

namespace matgeom::gltf {

// Scales emission beyond glTF's [0, 1] emissiveFactor (its member: emissiveStrength).
constexpr const char* kEmissiveStrength = "KHR_materials_emissive_strength";

// The index of refraction: `ior`, 1.5 when absent. Blender's importer sets the Principled IOR to
// 1.5 for every glTF material, with the extension or without it.
constexpr const char* kIor = "KHR_materials_ior";
constexpr double kDefaultIor = 1.5;

// A clear lacquer layer: clearcoatFactor x clearcoatTexture.R and clearcoatRoughnessFactor x
// clearcoatRoughnessTexture.G (both factors default to 0), clearcoatNormalTexture.
constexpr const char* kClearcoat = "KHR_materials_clearcoat";
// The channels of the extension's textures Blender's importer reads.
constexpr int kClearcoatChannel = 0;
constexpr int kClearcoatRoughnessChannel = 1;

// Where glTF keeps opacity (alphaMode BLEND or MASK): the base colour texture's alpha.
constexpr int kBaseColorAlphaChannel = 3;

// Glass: transmissionFactor (default 0) x transmissionTexture.R.
constexpr const char* kTransmission = "KHR_materials_transmission";
constexpr int kTransmissionChannel = 0;

// Cloth sheen: sheenColorFactor (default black) x sheenColorTexture.RGB (sRGB) and
// sheenRoughnessFactor (default 0) x sheenRoughnessTexture.A. Blender 3.4's importer makes them
// the Color and Sigma of a Velvet BSDF it adds to the Principled BSDF.
constexpr const char* kSheen = "KHR_materials_sheen";
constexpr int kSheenRoughnessChannel = 3;

// A textureInfo's own UV placement (offset, rotation, scale, texCoord): matmaterial/texture_transform.h.
constexpr const char* kTextureTransform = "KHR_texture_transform";

// The older specular-glossiness model (gltf_materials.cpp converts it to metallic-roughness).
constexpr const char* kSpecularGlossiness = "KHR_materials_pbrSpecularGlossiness";

// Integer positions, normals, tangents and UVs: it only widens the accessor formats, which the
// reader handles.
constexpr const char* kMeshQuantization = "KHR_mesh_quantization";

// The extensions a file may require (extensionsRequired): the ones the reader applies. Any other
// changes how geometry or images are stored (Draco, meshopt, KTX2 and WebP images) and would be
// misread if ignored.
constexpr std::array<const char*, 8> kReadExtensions = {kMeshQuantization, kClearcoat,      kIor,
                                                        kSheen,           kTransmission,   kTextureTransform,
                                                        kEmissiveStrength, kSpecularGlossiness};

}  // namespace matgeom::gltf
