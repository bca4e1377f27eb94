#include "matmaterial/material_inputs.h"

#include <stdexcept>
#include <string>

namespace matmaterial {

MaterialInputs::MaterialInputs() {
  for (const MaterialParameterInfo& info : kMaterialParameters) set(info.id, info.default_value);
}

MaterialInputs& MaterialInputs::set(MaterialParameter p, double value) { return set(p, glm::dvec3(value)); }

MaterialInputs& MaterialInputs::set(MaterialParameter p, const glm::dvec3& value) {
  (*this)[p].value = value;
  return *this;
}

MaterialInputs& MaterialInputs::set_image(MaterialParameter p, int image, int channel, const TextureTransform& transform) {
  const MaterialParameterInfo& info = material_parameter(p);
  if (!info.texturable) throw std::invalid_argument(std::string("material parameter ") + info.name + " cannot come from an image");
  if (channel < 0 || channel > 3) throw std::invalid_argument("image channel must be 0..3, got " + std::to_string(channel));
  (*this)[p].image = image;
  (*this)[p].channel = channel;
  (*this)[p].transform = transform;
  return *this;
}

MaterialInputs& MaterialInputs::set_metallic_roughness_image(int image, const TextureTransform& transform) {
  for (const MaterialParameter p : {MaterialParameter::Roughness, MaterialParameter::Metallic})
    set_image(p, image, material_parameter(p).packed_channel, transform);
  return *this;
}

}  // namespace matmaterial
