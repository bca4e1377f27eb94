#pragma once
// An object ready to render: its mesh (one part per material slot), the slots' metallic-roughness
// materials and the 8-bit images they reference. Produced by the glTF reader and the built-in
// objects; libmatrender turns it into scene materials (matrender/asset.h).
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "matgeom/mesh.h"

namespace matgeom {

// Decoded 8-bit image, rows top to bottom, channels interleaved (1..4).
struct ImagePixels {
  std::string name;  // file name or "<file>#image<k>" for embedded images
  int width = 0;
  int height = 0;
  int channels = 0;
  std::vector<uint8_t> data;
};

enum class TextureWrap { Repeat, Clamp };

// A material slot as Blender's glTF importer builds it (docs/conventions.md, glTF importer):
// base colour = factor x texture (sRGB); roughness = factor x texture.G, metallic = factor x texture.B
// (Non-Color); normal map with strength = normalTexture.scale.
struct MaterialDesc {
  std::string name;
  glm::dvec3 base_color{1.0};
  int base_color_image = -1;  // index into ObjectAsset::images, -1 = none
  double metallic = 1.0;
  double roughness = 1.0;
  int metallic_roughness_image = -1;
  int normal_image = -1;
  double normal_strength = 1.0;
  double specular = 0.5;
  double specular_tint = 0.0;
  TextureWrap wrap = TextureWrap::Repeat;
  int label_id = 0;  // material family id written to the label AOV
};

// The surface Blender gives geometry without a material: the Principled BSDF's defaults (grey
// 0.8, dielectric, roughness 0.5, specular 0.5).
MaterialDesc default_material(const std::string& name = "default");

struct ObjectAsset {
  TriangleMesh mesh;                     // part k uses materials[k]
  std::vector<MaterialDesc> materials;
  std::vector<ImagePixels> images;
};

}  // namespace matgeom
