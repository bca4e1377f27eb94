#include "matrender/material.h"

namespace matrender {

Material::Material() {
  for (const matmaterial::MaterialParameterInfo& info : matmaterial::kMaterialParameters) {
    ParameterValue& p = (*this)[info.id];
    p.value = glm::vec3(static_cast<float>(info.default_value));
    p.channel = info.packed_channel;
  }
}

Material& Material::set(MaterialParameter p, float value) { return set(p, glm::vec3(value)); }

Material& Material::set(MaterialParameter p, const glm::vec3& value) {
  (*this)[p].value = value;
  return *this;
}

bool Material::textured() const {
  for (const ParameterValue& p : parameters)
    if (p.texture) return true;
  return false;
}

namespace {

// Looked up at transform(k uv): the linear part, and with it the footprint's stretch, scales by k.
matmaterial::UvAffine repeated(matmaterial::UvAffine transform, float repeats) {
  transform.linear *= repeats;
  transform.stretch *= repeats;
  return transform;
}

}  // namespace

Material with_texture_repeats(const Material& material, float repeats) {
  Material result = material;
  for (ParameterValue& parameter : result.parameters)
    if (parameter.texture) parameter.uv_transform = repeated(parameter.uv_transform, repeats);
  if (result.normal_map) result.normal_map_uv_transform = repeated(result.normal_map_uv_transform, repeats);
  return result;
}

}  // namespace matrender
