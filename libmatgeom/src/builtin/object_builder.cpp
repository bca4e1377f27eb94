#include "builtin/object_builder.h"

#include <stdexcept>

#include "builtin/shapes.h"
#include "matgeom/tangents.h"
#include "matgeom/uv/uv_pass.h"
#include "matgeom/uv/uv_scale.h"

namespace matgeom::builtin {

uint32_t ObjectBuilder::add_part(const std::string& name, Finish finish) {
  asset_.mesh.part_names.push_back(name);
  BuiltinMaterial made = make_material(asset_, name, finish, random_);
  asset_.materials.push_back(std::move(made.material));
  tile_sizes_.resize(asset_.materials.size());
  tile_sizes_.back() = made.tile_size_m;
  return static_cast<uint32_t>(asset_.mesh.part_names.size() - 1);
}

uint32_t ObjectBuilder::add_part(const std::string& name, const matmaterial::MaterialInputs& material) {
  asset_.mesh.part_names.push_back(name);
  asset_.materials.push_back(material);
  return static_cast<uint32_t>(asset_.mesh.part_names.size() - 1);
}

int ObjectBuilder::add_image(matbase::ImagePixels image) {
  asset_.images.push_back(std::move(image));
  return static_cast<int>(asset_.images.size() - 1);
}

void ObjectBuilder::add(uint32_t part, const TriangleMesh& piece) {
  if (part >= asset_.mesh.part_names.size()) throw std::logic_error("ObjectBuilder: part added before its material");
  append_part(asset_.mesh, piece, part);
  ++plain_pieces_;
}

void ObjectBuilder::add_uv_mapped(const TriangleMesh& piece) {
  for (uint32_t part : piece.triangle_parts)
    if (part >= asset_.mesh.part_names.size()) throw std::logic_error("ObjectBuilder: part added before its material");
  if (piece.uvs.size() != piece.positions.size()) throw std::logic_error("ObjectBuilder: a UV-mapped piece without UVs");
  TriangleMesh& mesh = asset_.mesh;
  const uint32_t offset = static_cast<uint32_t>(mesh.positions.size());
  mesh.positions.insert(mesh.positions.end(), piece.positions.begin(), piece.positions.end());
  mesh.normals.insert(mesh.normals.end(), piece.normals.begin(), piece.normals.end());
  mesh.uvs.insert(mesh.uvs.end(), piece.uvs.begin(), piece.uvs.end());
  for (const glm::uvec3& t : piece.triangles) mesh.triangles.push_back(t + glm::uvec3(offset));
  mesh.triangle_parts.insert(mesh.triangle_parts.end(), piece.triangle_parts.begin(), piece.triangle_parts.end());
  ++uv_mapped_pieces_;
}

void ObjectBuilder::repeat_maps_to_size() {
  for (size_t part = 0; part < tile_sizes_.size(); ++part)
    if (tile_sizes_[part])
      asset_.materials[part] = with_texture_repeats(
          asset_.materials[part], texture_repeats(asset_.mesh, static_cast<uint32_t>(part), *tile_sizes_[part]));
}

ObjectAsset ObjectBuilder::finish() {
  if (uv_mapped_pieces_ > 0) {
    if (plain_pieces_ > 0) throw std::logic_error("ObjectBuilder: UV-mapped and plain pieces in one object");
    compute_tangents(asset_.mesh);
    repeat_maps_to_size();
    return std::move(asset_);
  }
  UvPassOptions options;
  options.tile_resolution = kBuiltinTileResolution;
  asset_.mesh = uv_pass(asset_.mesh, options).mesh;
  repeat_maps_to_size();
  return std::move(asset_);
}

}  // namespace matgeom::builtin
