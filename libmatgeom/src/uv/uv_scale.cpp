#include "matgeom/uv/uv_scale.h"

#include <cmath>

namespace matgeom {
namespace {

// The image looked up at transform(k uv) in our (Blender's, v-up) UVs, as
// matrender::with_texture_repeats repeats it and a Blender Mapping node's Scale does: k times
// about the origin of Blender's UVs, which is (0, 1) in glTF's (v down). Scaling S alone would
// repeat about glTF's origin, the image's top-left corner, and shift it by k - 1 in v.
matmaterial::TextureTransform repeated(matmaterial::TextureTransform transform, double repeats) {
  const double s = std::sin(transform.rotation), c = std::cos(transform.rotation);
  transform.offset -= (repeats - 1.0) * transform.scale.y * glm::dvec2(s, c);
  transform.scale *= repeats;
  return transform;
}

}  // namespace

std::optional<double> metres_per_uv_unit(const TriangleMesh& mesh, uint32_t part) {
  if (mesh.uvs.size() != mesh.positions.size()) return std::nullopt;
  double surface = 0.0, uv = 0.0;
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    if ((mesh.triangle_parts.empty() ? 0u : mesh.triangle_parts[t]) != part) continue;
    const glm::uvec3& tri = mesh.triangles[t];
    const glm::dvec3 p0(mesh.positions[tri.x]), p1(mesh.positions[tri.y]), p2(mesh.positions[tri.z]);
    const glm::dvec2 u0(mesh.uvs[tri.x]), u1(mesh.uvs[tri.y]), u2(mesh.uvs[tri.z]);
    surface += 0.5 * glm::length(glm::cross(p1 - p0, p2 - p0));
    const glm::dvec2 a = u1 - u0, b = u2 - u0;
    uv += 0.5 * std::abs(a.x * b.y - a.y * b.x);
  }
  if (!(uv > 0.0) || !(surface > 0.0) || !std::isfinite(surface / uv)) return std::nullopt;
  return std::sqrt(surface / uv);
}

double texture_repeats(const TriangleMesh& mesh, uint32_t part, double tile_size_m) {
  const std::optional<double> metres = metres_per_uv_unit(mesh, part);
  return metres && tile_size_m > 0.0 ? *metres / tile_size_m : 1.0;
}

matmaterial::MaterialInputs with_texture_repeats(const matmaterial::MaterialInputs& material, double repeats) {
  matmaterial::MaterialInputs result = material;
  for (matmaterial::MaterialInput& input : result.inputs)
    if (input.image >= 0) input.transform = repeated(input.transform, repeats);
  if (result.normal_image >= 0) result.normal_transform = repeated(result.normal_transform, repeats);
  return result;
}

void assign_material_to_all_parts(ObjectAsset& asset, const matmaterial::FolderMaterial& material) {
  asset.images = material.images;
  for (size_t part = 0; part < asset.materials.size(); ++part) {
    const std::string name = asset.materials[part].name;
    asset.materials[part] =
        material.tile_size_m
            ? with_texture_repeats(material.material,
                                   texture_repeats(asset.mesh, static_cast<uint32_t>(part), *material.tile_size_m))
            : material.material;
    asset.materials[part].name = name;
  }
}

}  // namespace matgeom
