#include "matrender/asset.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace matrender {
namespace {

Wrap to_wrap(matgeom::TextureWrap wrap) {
  return wrap == matgeom::TextureWrap::Clamp ? Wrap::Clamp : Wrap::Repeat;
}

TexturePtr image_or_null(const std::vector<TexturePtr>& images, int index, const std::string& material) {
  if (index < 0) return nullptr;
  if (static_cast<size_t>(index) >= images.size())
    throw std::invalid_argument("material " + material + ": image index " + std::to_string(index) +
                                " out of range");
  return images[static_cast<size_t>(index)];
}

}  // namespace

Material material_from_desc(const matgeom::MaterialDesc& desc, const std::vector<TexturePtr>& images_as_srgb,
                            const std::vector<TexturePtr>& images_as_data) {
  using P = MaterialParameter;
  Material m;
  m.name = desc.name;
  m.label_id = desc.label_id;
  m.set(P::Specular, static_cast<float>(desc.specular));
  m.set(P::SpecularTint, static_cast<float>(desc.specular_tint));
  m.set(P::BaseColor, glm::vec3(desc.base_color));
  m[P::BaseColor].texture = image_or_null(images_as_srgb, desc.base_color_image, desc.name);
  m.set(P::Roughness, static_cast<float>(desc.roughness));
  m.set(P::Metallic, static_cast<float>(desc.metallic));
  // Roughness and metallic read their channels of one packed image (glTF: G and B).
  if (TexturePtr packed = image_or_null(images_as_data, desc.metallic_roughness_image, desc.name)) {
    m[P::Roughness].texture = packed;
    m[P::Metallic].texture = packed;
  }
  m.normal_map = image_or_null(images_as_data, desc.normal_image, desc.name);
  m.normal_strength = static_cast<float>(desc.normal_strength);
  return m;
}

std::vector<uint32_t> add_asset(Scene& scene, const matgeom::ObjectAsset& asset,
                                const std::vector<std::optional<uint32_t>>& material_overrides,
                                const MeshOptions& options) {
  std::vector<TexturePtr> as_srgb(asset.images.size()), as_data(asset.images.size());
  auto decode = [&](int index, ColorSpace space, matgeom::TextureWrap wrap, std::vector<TexturePtr>& decoded) {
    if (index < 0 || static_cast<size_t>(index) >= asset.images.size() || decoded[static_cast<size_t>(index)]) return;
    const matgeom::ImagePixels& image = asset.images[static_cast<size_t>(index)];
    decoded[static_cast<size_t>(index)] = Texture::from_pixels8(image.width, image.height, image.channels,
                                                                image.data.data(), space, to_wrap(wrap), image.name);
  };
  const size_t parts = std::max<size_t>(asset.mesh.part_count(), asset.materials.size());
  std::vector<uint32_t> ids(parts);
  for (size_t k = 0; k < parts; ++k) {
    if (k < material_overrides.size() && material_overrides[k]) {
      ids[k] = *material_overrides[k];
    } else if (k < asset.materials.size()) {
      const matgeom::MaterialDesc& slot = asset.materials[k];
      decode(slot.base_color_image, ColorSpace::SRGB, slot.wrap, as_srgb);
      decode(slot.metallic_roughness_image, ColorSpace::NonColor, slot.wrap, as_data);
      decode(slot.normal_image, ColorSpace::NonColor, slot.wrap, as_data);
      ids[k] = scene.add_material(material_from_desc(slot, as_srgb, as_data));
    } else {
      ids[k] = scene.add_material(Material{});
    }
  }
  scene.add_mesh(asset.mesh, ids, options);
  return ids;
}

}  // namespace matrender
