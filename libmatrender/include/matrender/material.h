#pragma once
// Principled BSDF parameters with Blender 3.4 Cycles semantics (docs/conventions.md).
#include <string>

#include <glm/glm.hpp>

#include "matrender/texture.h"

namespace matrender {

// A parameter is a constant, or a constant factor times a texture (Blender's importer multiplies
// glTF factors and textures the same way). A constant costs no lookup.
struct ColorParam {
  glm::vec3 value{0.8f};
  TexturePtr texture;  // when set, the result is value * texture RGB
};
struct ScalarParam {
  float value = 0.0f;
  TexturePtr texture;  // when set, the result is value * texture[channel]
  int channel = 0;     // which texture channel (0 = R, 1 = G, 2 = B, 3 = A)
};

enum class DiffuseModel {
  Principled,  // Cycles' principled diffuse with retro-reflection (the Principled BSDF node)
  Lambert,     // Cycles' Diffuse BSDF at roughness 0 (closed-form tests, simple scenes)
};

struct Material {
  std::string name = "material";
  int label_id = 0;  // material family id written to the label AOV
  DiffuseModel diffuse_model = DiffuseModel::Principled;
  ColorParam base_color{glm::vec3(0.8f), nullptr};
  ScalarParam metallic{0.0f, nullptr, 2};
  ScalarParam roughness{0.5f, nullptr, 1};
  float specular = 0.5f;
  float specular_tint = 0.0f;
  float ior = 1.45f;  // Blender's Principled IOR: the relative index a surface point carries
  TexturePtr normal_map;  // tangent space, OpenGL convention (+Y = +v), Non-Color
  float normal_strength = 1.0f;
};

}  // namespace matrender
