#include "builtin/object_builder.h"

#include <stdexcept>

#include "builtin/shapes.h"
#include "matgeom/uv_pass.h"

namespace matgeom::builtin {

uint32_t ObjectBuilder::add_part(const std::string& name, Finish finish) {
  asset_.mesh.part_names.push_back(name);
  asset_.materials.push_back(make_material(asset_, name, finish, random_));
  return static_cast<uint32_t>(asset_.mesh.part_names.size() - 1);
}

void ObjectBuilder::add(uint32_t part, const TriangleMesh& piece) {
  if (part >= asset_.mesh.part_names.size()) throw std::logic_error("ObjectBuilder: part added before its material");
  append_part(asset_.mesh, piece, part);
}

ObjectAsset ObjectBuilder::finish() {
  UvPassOptions options;
  options.tile_resolution = kBuiltinTileResolution;
  asset_.mesh = uv_pass(asset_.mesh, options).mesh;
  return std::move(asset_);
}

}  // namespace matgeom::builtin
