#pragma once
// The materials a scene description names, added to a Scene on first use so that unused ones
// load nothing: a texture file, material folder or library material shared by several materials
// is loaded or generated once. What build_scene assigns parts from, and what a tool keeps to put
// an object in other materials later without rebuilding its BVH (scene_builder.h).
#include <atomic>
#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <utility>

#include "matgeom/mesh.h"
#include "matrender/scene.h"
#include "matrender/scene_description.h"

namespace matrender {

class SceneMaterials {
 public:
  explicit SceneMaterials(std::map<std::string, MaterialDescription> described = {})
      : described_(std::move(described)) {}

  bool has(const std::string& name) const { return described_.count(name) != 0; }
  // Describes one more material, for a tool that draws materials after the scene is built (make_dataset's
  // surroundings); a name already described keeps its description.
  void describe(const std::string& name, MaterialDescription description) {
    described_.emplace(name, std::move(description));
  }

  // Loading stops with matbase::Cancelled once `cancel` is set: before each texture and folder,
  // and within a row of a library material's maps. A run's, not the scene's: set by the app.
  void cancel_on(const std::atomic<bool>* cancel) { cancel_ = cancel; }

  // The scene material id of the described material `name`, added to `scene` when first asked
  // for. Throws matbase::InputError naming the file when one of its inputs fails to load, and
  // std::out_of_range for a name not described.
  uint32_t id(Scene& scene, const std::string& name);

  // The material on part `part` of `mesh`: a material whose maps have a physical size (a folder's
  // metadata, the library's tiles) repeats them as often per UV unit as that part's UVs need at
  // the UV pass's own density. UVs made at `uv_scale` s times that density keep those repeats
  // per UV unit, so the maps repeat s times as often across the part (the paper's Figure 3);
  // without the scale they would be brought back to their physical size and s would show nothing.
  uint32_t id_on_part(Scene& scene, const std::string& name, const matgeom::TriangleMesh& mesh, uint32_t part,
                      double uv_scale = 1.0);

 private:
  TexturePtr texture(const std::optional<TextureFile>& file);
  Material folder_material(const std::string& name, const MaterialDescription& description);
  Material library_material(const std::string& name, const MaterialDescription& description);

  std::map<std::string, MaterialDescription> described_;
  std::map<std::string, uint32_t> ids_;
  std::map<std::tuple<std::string, ColorSpace, TextureWrap>, TexturePtr> textures_;
  std::map<std::string, Material> folder_materials_;   // by folder path
  std::map<std::string, Material> library_materials_;  // by canonical name and resolution
  std::map<std::string, double> folder_tile_sizes_, library_tile_sizes_;  // keyed as the two above
  std::map<std::string, double> tile_sizes_;  // metres per repeat of a scene material's maps, by name
  std::map<std::pair<std::string, float>, uint32_t> repeated_ids_;  // by name and repeats
  const std::atomic<bool>* cancel_ = nullptr;
};

}  // namespace matrender
