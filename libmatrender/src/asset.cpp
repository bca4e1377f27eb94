#include "matrender/asset.h"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>

namespace matrender {
namespace {

// The asset's images as textures, each decoded once per colour space and wrap it is used with.
class AssetTextures {
 public:
  explicit AssetTextures(const std::vector<matbase::ImagePixels>& images) : images_(images) {}

  TexturePtr texture(int index, ColorSpace space, matmaterial::TextureWrap wrap, const std::string& material) {
    if (index < 0) return nullptr;
    if (static_cast<size_t>(index) >= images_.size())
      throw std::invalid_argument("material " + material + ": image index " + std::to_string(index) +
                                  " out of range");
    TexturePtr& decoded = decoded_[std::make_tuple(index, space, wrap)];
    if (!decoded) {
      const matbase::ImagePixels& image = images_[static_cast<size_t>(index)];
      decoded = Texture::from_pixels8(image.width, image.height, image.channels, image.data.data(), space,
                                      wrap, image.name);
    }
    return decoded;
  }

 private:
  const std::vector<matbase::ImagePixels>& images_;
  std::map<std::tuple<int, ColorSpace, matmaterial::TextureWrap>, TexturePtr> decoded_;
};

// Every input of the parameter table carries over: its constant, and its image decoded in the
// table's colour space; the normal map is Non-Color.
Material material_with_textures(const matmaterial::MaterialInputs& desc, AssetTextures& textures) {
  Material m;
  m.name = desc.name;
  m.label_id = desc.label_id;
  for (const matmaterial::MaterialParameterInfo& info : matmaterial::kMaterialParameters) {
    const matmaterial::MaterialInput& input = desc[info.id];
    ParameterValue& value = m[info.id];
    value.value = glm::vec3(input.value);
    value.texture = textures.texture(input.image, info.texture_space, desc.wrap, desc.name);
    value.channel = input.channel;
    value.uv_transform = matmaterial::uv_affine(input.transform);
    if (value.texture && !info.texturable)
      throw std::invalid_argument("material " + desc.name + ": " + info.name + " cannot come from an image");
  }
  m.normal_map = textures.texture(desc.normal_image, ColorSpace::NonColor, desc.wrap, desc.name);
  m.normal_strength = static_cast<float>(desc.normal_strength);
  m.normal_map_uv_transform = matmaterial::uv_affine(desc.normal_transform);
  m.vertex_colors = desc.vertex_colors;
  return m;
}

}  // namespace

Material material_from_desc(const matmaterial::MaterialInputs& desc, const std::vector<matbase::ImagePixels>& images) {
  AssetTextures textures(images);
  return material_with_textures(desc, textures);
}

std::vector<uint32_t> add_asset(Scene& scene, const matgeom::ObjectAsset& asset,
                                const std::vector<std::optional<uint32_t>>& material_overrides,
                                const MeshOptions& options) {
  AssetTextures textures(asset.images);
  const size_t parts = std::max<size_t>(asset.mesh.part_count(), asset.materials.size());
  std::vector<uint32_t> ids(parts);
  for (size_t k = 0; k < parts; ++k) {
    if (k < material_overrides.size() && material_overrides[k]) {
      ids[k] = *material_overrides[k];
    } else if (k < asset.materials.size()) {
      ids[k] = scene.add_material(material_with_textures(asset.materials[k], textures));
    } else {
      ids[k] = scene.add_material(Material{});
    }
  }
  scene.add_mesh(asset.mesh, ids, options);
  return ids;
}

}  // namespace matrender
