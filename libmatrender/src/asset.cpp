#include "matrender/asset.h"

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
  Material m;
  m.name = desc.name;
  m.label_id = desc.label_id;
  m.specular = static_cast<float>(desc.specular);
  m.specular_tint = static_cast<float>(desc.specular_tint);
  m.base_color.value = glm::vec3(desc.base_color);
  m.base_color.texture = image_or_null(images_as_srgb, desc.base_color_image, desc.name);
  m.roughness.value = static_cast<float>(desc.roughness);
  m.metallic.value = static_cast<float>(desc.metallic);
  if (TexturePtr orm = image_or_null(images_as_data, desc.metallic_roughness_image, desc.name)) {
    m.roughness.texture = orm;
    m.roughness.channel = 1;  // G
    m.metallic.texture = orm;
    m.metallic.channel = 2;   // B
  }
  m.normal_map = image_or_null(images_as_data, desc.normal_image, desc.name);
  m.normal_strength = static_cast<float>(desc.normal_strength);
  return m;
}

std::vector<uint32_t> add_asset(Scene& scene, const matgeom::ObjectAsset& asset) {
  // Each image is decoded once per colour space it is used in.
  std::vector<TexturePtr> as_srgb(asset.images.size()), as_data(asset.images.size());
  auto wrap_of = [&](size_t image) {
    for (const matgeom::MaterialDesc& d : asset.materials)
      if (d.base_color_image == static_cast<int>(image) || d.metallic_roughness_image == static_cast<int>(image) ||
          d.normal_image == static_cast<int>(image))
        return to_wrap(d.wrap);
    return Wrap::Repeat;
  };
  for (size_t i = 0; i < asset.images.size(); ++i) {
    const matgeom::ImagePixels& img = asset.images[i];
    bool srgb_use = false, data_use = false;
    for (const matgeom::MaterialDesc& d : asset.materials) {
      srgb_use |= d.base_color_image == static_cast<int>(i);
      data_use |= d.metallic_roughness_image == static_cast<int>(i) || d.normal_image == static_cast<int>(i);
    }
    if (srgb_use)
      as_srgb[i] = Texture::from_pixels8(img.width, img.height, img.channels, img.data.data(), ColorSpace::SRGB,
                                         wrap_of(i), img.name);
    if (data_use)
      as_data[i] = Texture::from_pixels8(img.width, img.height, img.channels, img.data.data(), ColorSpace::NonColor,
                                         wrap_of(i), img.name);
  }
  std::vector<uint32_t> ids;
  for (const matgeom::MaterialDesc& desc : asset.materials)
    ids.push_back(scene.add_material(material_from_desc(desc, as_srgb, as_data)));
  if (ids.empty()) ids.push_back(scene.add_material(Material{}));
  scene.add_mesh(asset.mesh, ids);
  return ids;
}

}  // namespace matrender
