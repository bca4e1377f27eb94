#pragma once
// The same material for the fast BSDF and for the double-precision reference in shaders_ref.
#include <glm/glm.hpp>

#include "bsdf/principled.h"
#include "shaders_ref/principled_reference.h"

inline shaders_ref::PrincipledParams reference_params(const matrender::PrincipledInputs& in) {
  shaders_ref::PrincipledParams p;
  p.base_color = glm::dvec3(in.color(matrender::MaterialParameter::BaseColor));
  p.metallic = in.scalar(matrender::MaterialParameter::Metallic);
  p.roughness = in.scalar(matrender::MaterialParameter::Roughness);
  p.specular = in.scalar(matrender::MaterialParameter::Specular);
  p.specular_tint = in.scalar(matrender::MaterialParameter::SpecularTint);
  p.sheen = in.scalar(matrender::MaterialParameter::Sheen);
  p.sheen_tint = in.scalar(matrender::MaterialParameter::SheenTint);
  p.clearcoat = in.scalar(matrender::MaterialParameter::Clearcoat);
  p.clearcoat_roughness = in.scalar(matrender::MaterialParameter::ClearcoatRoughness);
  p.transmission = in.scalar(matrender::MaterialParameter::Transmission);
  p.transmission_roughness = in.scalar(matrender::MaterialParameter::TransmissionRoughness);
  p.ior = in.scalar(matrender::MaterialParameter::Ior);
  p.velvet_color = glm::dvec3(in.color(matrender::MaterialParameter::VelvetColor));
  p.velvet_sigma = in.scalar(matrender::MaterialParameter::VelvetSigma);
  p.lambert_diffuse = in.diffuse_model == matrender::DiffuseModel::Lambert;
  return p;
}
