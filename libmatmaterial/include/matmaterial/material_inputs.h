#pragma once
// A material slot as every reader, the material library and the renderer's asset loader describe
// it: one input per row of the Principled parameter table, each a constant or a factor times an
// image (an index into the images the description travels with), plus a tangent-space normal map.
#include <array>
#include <cstddef>
#include <string>
#include <utility>

#include <glm/glm.hpp>

#include "matmaterial/material_parameters.h"
#include "matmaterial/texture_transform.h"

namespace matmaterial {

// One Principled parameter of a material slot: a constant, or the constant times an image of the
// asset (a factor, as glTF and Blender's importers multiply them): its RGB for a colour, one
// channel for a scalar.
struct MaterialInput {
  glm::dvec3 value{0.0};  // a scalar is held in every channel
  int image = -1;         // index into ObjectAsset::images, -1 = constant
  int channel = 0;        // scalars: the image channel read (0 R, 1 G, 2 B, 3 A)
  TextureTransform transform;  // where the image lies on the UVs (glTF's KHR_texture_transform)
};

// A material slot: one input per row of the parameter table (matmaterial/material_parameters.h),
// read in the colour space the table gives, plus a tangent-space normal map. The readers map
// their formats onto it as Blender's importers do (docs/conventions.md).
struct MaterialInputs {
  // Every input at Blender's default (the table's), no images: the surface Blender gives geometry
  // without a material.
  MaterialInputs();
  explicit MaterialInputs(std::string slot_name) : MaterialInputs() { name = std::move(slot_name); }

  std::string name;
  std::array<MaterialInput, kMaterialParameterCount> inputs;
  int normal_image = -1;  // tangent space, OpenGL convention, Non-Color
  double normal_strength = 1.0;
  TextureTransform normal_transform;
  TextureWrap wrap = TextureWrap::Repeat;
  int label_id = 0;  // material family id written to the label AOV
  // The base colour times the mesh's vertex colours (TriangleMesh::colors) where it has them:
  // Blender's Color Attribute node multiplied in, as its glTF importer wires COLOR_0.
  bool vertex_colors = false;

  MaterialInput& operator[](MaterialParameter p) { return inputs[static_cast<size_t>(p)]; }
  const MaterialInput& operator[](MaterialParameter p) const { return inputs[static_cast<size_t>(p)]; }
  // A constant (or the factor of an image): set(MaterialParameter::Roughness, 0.3).
  MaterialInputs& set(MaterialParameter p, double value);
  MaterialInputs& set(MaterialParameter p, const glm::dvec3& value);
  // The parameter comes from image `image` (times its value); a scalar reads `channel`.
  MaterialInputs& set_image(MaterialParameter p, int image, int channel = 0, const TextureTransform& transform = {});
  // Roughness and metallic from glTF's packed image: its G and B (the table's packed channels).
  MaterialInputs& set_metallic_roughness_image(int image, const TextureTransform& transform = {});
  glm::dvec3 color(MaterialParameter p) const { return (*this)[p].value; }
  double scalar(MaterialParameter p) const { return (*this)[p].value.x; }
};

}  // namespace matmaterial
