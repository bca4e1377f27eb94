#include "matrender/material.h"

namespace matrender {

Material::Material() {
  for (const matgeom::MaterialParameterInfo& info : matgeom::kMaterialParameters) {
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

}  // namespace matrender
