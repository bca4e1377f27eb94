#pragma once
// A material: the Principled BSDF's parameters (matmaterial/material_parameters.h, the one table of
// them) with Blender 3.4 Cycles semantics (docs/conventions.md), each a constant or a texture.
#include <array>
#include <string>

#include <glm/glm.hpp>

#include "matmaterial/material_parameters.h"
#include "matmaterial/texture_transform.h"
#include "matrender/texture.h"

namespace matrender {

using matmaterial::MaterialParameter;

// One parameter: a constant, or a constant factor times a texture (Blender's importer multiplies
// glTF factors and textures the same way). A constant costs no lookup.
struct ParameterValue {
  glm::vec3 value{0.0f};  // a colour; a scalar is held in every channel
  TexturePtr texture;     // when set: value * texture RGB (colour) or value * texture[channel] (scalar)
  int channel = 0;        // scalars: which texture channel (0 = R, 1 = G, 2 = B, 3 = A)
  matmaterial::UvAffine uv_transform;  // the texture is looked up at uv_transform.apply(uv)
};

enum class DiffuseModel {
  Principled,  // Cycles' principled diffuse with retro-reflection (the Principled BSDF node)
  Lambert,     // Cycles' Diffuse BSDF at roughness 0 (closed-form tests, simple scenes)
};

// The Principled BSDF's Distribution for its specular lobe: Cycles 3.4's single-scatter GGX
// (Blender's default) or Multiscatter GGX, which also reflects the light that bounces between
// microfacets (rough metals lose less energy). Glass stays single-scatter either way.
enum class SpecularDistribution { GGX, MultiscatterGGX };

struct Material {
  // Every parameter at Blender's default; scalar texture channels at their place in a packed
  // metallic-roughness image.
  Material();

  std::string name = "material";
  int label_id = 0;  // material family id written to the label AOV
  DiffuseModel diffuse_model = DiffuseModel::Principled;
  SpecularDistribution distribution = SpecularDistribution::GGX;
  std::array<ParameterValue, matmaterial::kMaterialParameterCount> parameters;
  TexturePtr normal_map;  // tangent space, OpenGL convention (+Y = +v), Non-Color
  float normal_strength = 1.0f;
  matmaterial::UvAffine normal_map_uv_transform;
  // The base colour times the hit mesh's interpolated vertex colours where it has them
  // (matmaterial::MaterialInputs::vertex_colors).
  bool vertex_colors = false;

  ParameterValue& operator[](MaterialParameter p) { return parameters[static_cast<size_t>(p)]; }
  const ParameterValue& operator[](MaterialParameter p) const { return parameters[static_cast<size_t>(p)]; }
  // A constant value: set(MaterialParameter::Roughness, 0.3f), set(MaterialParameter::BaseColor, rgb).
  Material& set(MaterialParameter p, float value);
  Material& set(MaterialParameter p, const glm::vec3& value);
  // The constant (the factor of a texture); a scalar's is x.
  glm::vec3 color(MaterialParameter p) const { return (*this)[p].value; }
  float scalar(MaterialParameter p) const { return (*this)[p].value.x; }
  // Some parameter comes from a texture.
  bool textured() const;
};

// The material with every texture it reads (parameters and normal map) repeated `repeats` times
// per UV unit, on top of its own transforms: what a material folder's physical tile size asks of
// a part whose UV unit is `repeats` tiles long (matgeom/uv/uv_scale.h).
Material with_texture_repeats(const Material& material, float repeats);

}  // namespace matrender
