#include "matrender/scene_materials.h"

#include <exception>

#include "matbase/cancellation.h"
#include "matgeom/uv/uv_scale.h"
#include "matmaterial/folder/material_folder.h"
#include "matmaterial/library/material_library.h"
#include "matrender/asset.h"

namespace matrender {

uint32_t SceneMaterials::id(Scene& scene, const std::string& name) {
  if (const auto it = ids_.find(name); it != ids_.end()) return it->second;
  const MaterialDescription& description = described_.at(name);
  if (description.folder) return ids_[name] = scene.add_material(folder_material(name, description));
  if (description.library) return ids_[name] = scene.add_material(library_material(name, description));
  Material material = description.constants;
  for (size_t k = 0; k < material.parameters.size(); ++k) material.parameters[k].texture = texture(description.textures[k]);
  material.normal_map = texture(description.normal_map);
  return ids_[name] = scene.add_material(std::move(material));
}

uint32_t SceneMaterials::id_on_part(Scene& scene, const std::string& name, const matgeom::TriangleMesh& mesh,
                                    uint32_t part, double uv_scale) {
  const uint32_t base = id(scene, name);
  const auto tile = tile_sizes_.find(name);
  if (tile == tile_sizes_.end()) return base;
  // The part's metres per UV unit are 1/s of the unscaled pass's: s times them is its repeats.
  const double repeats = matgeom::texture_repeats(mesh, part, tile->second) * uv_scale;
  if (repeats == 1.0) return base;
  const auto key = std::make_pair(name, static_cast<float>(repeats));
  if (const auto it = repeated_ids_.find(key); it != repeated_ids_.end()) return it->second;
  return repeated_ids_[key] = scene.add_material(with_texture_repeats(scene.material(base), key.second));
}

TexturePtr SceneMaterials::texture(const std::optional<TextureFile>& file) {
  if (!file) return nullptr;
  TexturePtr& loaded = textures_[std::make_tuple(file->path, file->color_space, file->wrap)];
  if (!loaded) {
    matbase::throw_if_cancelled(cancel_);
    try {
      loaded = Texture::load(file->path, file->color_space, file->wrap);
    } catch (const std::exception& e) {
      throw file->origin.error("/texture", e.what());
    }
  }
  return loaded;
}

// A folder used by several materials (or given in place on several objects) is read once.
Material SceneMaterials::folder_material(const std::string& name, const MaterialDescription& description) {
  const MaterialFolderFile& file = *description.folder;
  auto read = folder_materials_.find(file.path);
  if (read == folder_materials_.end()) {
    matmaterial::FolderMaterial folder;
    matbase::throw_if_cancelled(cancel_);
    try {
      folder = matmaterial::read_material_folder(file.path);
    } catch (const std::exception& e) {
      throw file.origin.error("", e.what());
    }
    read = folder_materials_.emplace(file.path, material_from_desc(folder.material, folder.images)).first;
    if (folder.tile_size_m) folder_tile_sizes_[file.path] = *folder.tile_size_m;
  }
  if (const auto tile = folder_tile_sizes_.find(file.path); tile != folder_tile_sizes_.end())
    tile_sizes_[name] = tile->second;
  Material material = read->second;
  material.name = name;
  if (description.label_id) material.label_id = *description.label_id;
  return material;
}

// A library material asked for by several scene materials is generated once.
Material SceneMaterials::library_material(const std::string& name, const MaterialDescription& description) {
  const LibraryMaterialRequest& request = *description.library;
  const std::string key = matmaterial::library_material_name(request.spec) + "@" + std::to_string(request.resolution);
  auto made = library_materials_.find(key);
  if (made == library_materials_.end()) {
    matmaterial::FolderMaterial generated;
    try {
      generated = matmaterial::generate_library_material(request.spec, {request.resolution, 0, cancel_});
    } catch (const matbase::Cancelled&) {
      throw;
    } catch (const std::exception& e) {
      throw request.origin.error("", e.what());
    }
    made = library_materials_.emplace(key, material_from_desc(generated.material, generated.images)).first;
    library_tile_sizes_[key] = *generated.tile_size_m;
  }
  tile_sizes_[name] = library_tile_sizes_.at(key);
  Material material = made->second;
  material.name = name;
  if (description.label_id) material.label_id = *description.label_id;
  return material;
}

}  // namespace matrender
