#pragma once
// The same material for the fast BSDF and for the double-precision reference in shaders_ref.
#include <glm/glm.hpp>

#include "bsdf/principled.h"
#include "shaders_ref/principled_reference.h"

inline shaders_ref::PrincipledParams reference_params(const matrender::PrincipledInputs& in) {
  shaders_ref::PrincipledParams p;
  p.base_color = glm::dvec3(in.base_color);
  p.metallic = in.metallic;
  p.roughness = in.roughness;
  p.specular = in.specular;
  p.specular_tint = in.specular_tint;
  p.lambert_diffuse = in.diffuse_model == matrender::DiffuseModel::Lambert;
  return p;
}
