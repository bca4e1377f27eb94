#include "io/gltf/metallic_roughness_image.h"

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <utility>

#include "matbase/image/image_pixels.h"

namespace matgeom::gltf {
namespace {

using P = matmaterial::MaterialParameter;

int gltf_channel(P p) { return matmaterial::material_parameter(p).packed_channel; }

const matbase::ImagePixels* image_of(const matmaterial::MaterialInput& input, const std::vector<matbase::ImagePixels>& images, P p,
                            const std::string& what) {
  if (input.image < 0) return nullptr;
  const char* name = matmaterial::material_parameter(p).name;
  if (static_cast<size_t>(input.image) >= images.size())
    throw std::invalid_argument("write_gltf: " + what + " " + name + " refers to image " + std::to_string(input.image) +
                                " but the asset has " + std::to_string(images.size()));
  const matbase::ImagePixels& pixels = images[static_cast<size_t>(input.image)];
  if (input.channel < 0 || input.channel > 3)
    throw std::invalid_argument("write_gltf: " + what + " " + name + " reads image channel " +
                                std::to_string(input.channel) + "; channels are 0 to 3");
  if (!matbase::is_well_formed(pixels))
    throw std::invalid_argument("write_gltf: image " + std::to_string(input.image) + " (" + pixels.name +
                                ") has inconsistent size or channels");
  return &pixels;
}

bool channel_is_one(const matbase::ImagePixels& pixels, int channel) {
  const size_t texels = pixels.data.size() / static_cast<size_t>(pixels.channels);
  for (size_t i = 0; i < texels; ++i)
    if (matbase::texel_channel(pixels, i, channel) != 255) return false;
  return true;
}

// The texel of `source` nearest to texel (x, y) of a width x height image.
uint8_t nearest(const matbase::ImagePixels& source, int channel, int x, int y, int width, int height) {
  const int sx = std::min(source.width - 1, x * source.width / width);
  const int sy = std::min(source.height - 1, y * source.height / height);
  return matbase::texel_channel(source, static_cast<size_t>(sy) * static_cast<size_t>(source.width) + static_cast<size_t>(sx),
                       channel);
}

}  // namespace

MetallicRoughnessImage metallic_roughness_image(const matmaterial::MaterialInputs& material, const std::vector<matbase::ImagePixels>& images,
                                                const std::string& what) {
  const matmaterial::MaterialInput& roughness = material[P::Roughness];
  const matmaterial::MaterialInput& metallic = material[P::Metallic];
  const matbase::ImagePixels* roughness_image = image_of(roughness, images, P::Roughness, what);
  const matbase::ImagePixels* metallic_image = image_of(metallic, images, P::Metallic, what);
  if (!roughness_image && !metallic_image) return {};

  const bool roughness_in_place = roughness_image && roughness.channel == gltf_channel(P::Roughness);
  const bool metallic_in_place = metallic_image && metallic.channel == gltf_channel(P::Metallic);
  if (roughness_in_place && metallic_in_place && roughness.image == metallic.image) return {roughness.image, {}};
  if (roughness_in_place && !metallic_image && channel_is_one(*roughness_image, gltf_channel(P::Metallic)))
    return {roughness.image, {}};
  if (metallic_in_place && !roughness_image && channel_is_one(*metallic_image, gltf_channel(P::Roughness)))
    return {metallic.image, {}};

  matbase::ImagePixels packed = matbase::blank_image(
      (roughness_image ? roughness_image->name : "") + "+" + (metallic_image ? metallic_image->name : ""),
      std::max(roughness_image ? roughness_image->width : 0, metallic_image ? metallic_image->width : 0),
      std::max(roughness_image ? roughness_image->height : 0, metallic_image ? metallic_image->height : 0), 3);
  for (int y = 0; y < packed.height; ++y) {
    for (int x = 0; x < packed.width; ++x) {
      uint8_t* texel = &packed.data[(static_cast<size_t>(y) * static_cast<size_t>(packed.width) + static_cast<size_t>(x)) * 3];
      texel[gltf_channel(P::Roughness)] =
          roughness_image ? nearest(*roughness_image, roughness.channel, x, y, packed.width, packed.height) : 255;
      texel[gltf_channel(P::Metallic)] =
          metallic_image ? nearest(*metallic_image, metallic.channel, x, y, packed.width, packed.height) : 255;
    }
  }
  return {-1, std::move(packed)};
}

}  // namespace matgeom::gltf
