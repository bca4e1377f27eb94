#include "builtin/materials.h"

#include "matmaterial/library/material_library.h"

namespace matgeom::builtin {
namespace {

using MC = matmaterial::MaterialClass;

matmaterial::LibraryMaterialSpec library_spec(Finish finish, matbase::UniformSource& random) {
  const uint32_t seed = random.bits();
  switch (finish) {
    case Finish::Wood:
      return {MC::Wood, random.next() < 0.5 ? "raw" : "lacquered", seed};
    case Finish::PaintedWood:
      return {MC::Wood, "painted", seed};
    case Finish::Fabric:
      return {MC::Fabric, "", seed};
    case Finish::Leather:
      return {MC::Leather, "", seed};
    case Finish::BrushedMetal:
      return {MC::Metal, "brushed", seed};
    case Finish::Plastic:
      return {MC::Plastic, "glossy", seed};
    case Finish::Ceramic:
      return {MC::Ceramic, "", seed};
    case Finish::Concrete:
      return {MC::Concrete, "cast", seed};
    case Finish::Paper:
      return {MC::Paper, "sheet", seed};
    case Finish::Wicker:
      return {MC::Wood, "wicker", seed};
  }
  return {MC::Plastic, "glossy", seed};
}

// Appends `image` of `generated` to the asset, if it is one, and returns its new index.
int moved_image(ObjectAsset& asset, matmaterial::FolderMaterial& generated, int image) {
  if (image < 0) return -1;
  asset.images.push_back(std::move(generated.images[static_cast<size_t>(image)]));
  return static_cast<int>(asset.images.size() - 1);
}

}  // namespace

BuiltinMaterial make_material(ObjectAsset& asset, const std::string& slot, Finish finish, matbase::UniformSource& random) {
  matmaterial::FolderMaterial generated =
      matmaterial::generate_library_material(library_spec(finish, random), {kBuiltinTextureSize, 1});
  // The images the material reads: the height map shades nothing.
  BuiltinMaterial result{generated.material, *generated.tile_size_m};
  result.material.name = slot;
  for (matmaterial::MaterialInput& input : result.material.inputs) input.image = moved_image(asset, generated, input.image);
  result.material.normal_image = moved_image(asset, generated, result.material.normal_image);
  return result;
}

}  // namespace matgeom::builtin
