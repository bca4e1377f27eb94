// metres_per_uv_unit and texture repeats (matgeom/uv/uv_scale.h): a 2 m square mapped onto the unit
// UV square spans 2 m per UV unit; maps 0.5 m long repeat four times over it.
#include "matgeom/uv/uv_scale.h"

#include <catch2/catch.hpp>

#include "matmaterial/texture_transform.h"

using namespace matgeom;

namespace {

// Two parts: a square `size` metres wide with UVs over [0, uv_size]^2, and a second square with
// all its UVs at one point.
TriangleMesh two_squares(float size, float uv_size) {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {size, 0, 0}, {size, size, 0}, {0, size, 0},
                 {0, 0, 1}, {1, 0, 1},    {1, 1, 1},       {0, 1, 1}};
  m.uvs = {{0, 0}, {uv_size, 0}, {uv_size, uv_size}, {0, uv_size}, {0.5f, 0.5f}, {0.5f, 0.5f}, {0.5f, 0.5f}, {0.5f, 0.5f}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}};
  m.triangle_parts = {0, 0, 1, 1};
  m.part_names = {"square", "collapsed"};
  return m;
}

}  // namespace

TEST_CASE("A part's metres per UV unit is the square root of its area ratio", "[geom]") {
  const TriangleMesh mesh = two_squares(2.0f, 1.0f);
  REQUIRE(metres_per_uv_unit(mesh, 0));
  CHECK(*metres_per_uv_unit(mesh, 0) == Approx(2.0));
  CHECK(*metres_per_uv_unit(two_squares(3.0f, 0.5f), 0) == Approx(6.0));
  CHECK(texture_repeats(mesh, 0, 0.5) == Approx(4.0));
  // No UV area, no part, no UVs: no scale, and the maps keep their own.
  CHECK_FALSE(metres_per_uv_unit(mesh, 1));
  CHECK_FALSE(metres_per_uv_unit(mesh, 7));
  TriangleMesh no_uvs = mesh;
  no_uvs.uvs.clear();
  CHECK_FALSE(metres_per_uv_unit(no_uvs, 0));
  CHECK(texture_repeats(mesh, 1, 0.5) == 1.0);
}

TEST_CASE("with_texture_repeats scales the transforms of the images a material reads, only", "[geom]") {
  matmaterial::MaterialInputs material;
  material.set_image(matmaterial::MaterialParameter::BaseColor, 0);
  material[matmaterial::MaterialParameter::BaseColor].transform.scale = {2.0, 3.0};
  material.normal_image = 1;
  const matmaterial::MaterialInputs repeated = with_texture_repeats(material, 4.0);
  CHECK(repeated[matmaterial::MaterialParameter::BaseColor].transform.scale == glm::dvec2(8.0, 12.0));
  CHECK(repeated.normal_transform.scale == glm::dvec2(4.0));
  CHECK(repeated[matmaterial::MaterialParameter::Roughness].transform.is_identity());  // a constant: nothing to repeat
}

TEST_CASE("Repeated maps stay anchored at the origin of our UVs, wherever glTF's lies", "[geom]") {
  // Not a whole number of repeats: a shift by whole tiles would hide under the wrap.
  const double k = 1.46;
  const auto lookup = [](const matmaterial::TextureTransform& t, glm::vec2 uv) { return matmaterial::uv_affine(t).apply(uv); };
  matmaterial::MaterialInputs material;
  material.normal_image = 0;
  // Unplaced: the image repeats k times from (0, 0), so (u, v) reads the image at (k u, k v).
  const matmaterial::TextureTransform plain = with_texture_repeats(material, k).normal_transform;
  for (const glm::vec2 uv : {glm::vec2(0.0f), glm::vec2(1.0f, 0.0f), glm::vec2(0.0f, 1.0f), glm::vec2(0.3f, 0.8f)}) {
    const glm::vec2 read = lookup(plain, uv);
    CHECK(read.x == Approx(k * uv.x).margin(1e-5));
    CHECK(read.y == Approx(k * uv.y).margin(1e-5));
  }
  // Placed (moved, turned, stretched): the repeated placement reads at (k u, k v) what the
  // original read there.
  material.normal_transform = matmaterial::TextureTransform{{0.25, -0.5}, 0.75, {2.0, 3.0}};
  const matmaterial::TextureTransform placed = with_texture_repeats(material, k).normal_transform;
  for (const glm::vec2 uv : {glm::vec2(0.0f), glm::vec2(1.0f, 0.0f), glm::vec2(0.3f, 0.8f), glm::vec2(-1.5f, 2.25f)}) {
    const glm::vec2 expected = lookup(material.normal_transform, static_cast<float>(k) * uv);
    const glm::vec2 read = lookup(placed, uv);
    CHECK(read.x == Approx(expected.x).margin(1e-4));
    CHECK(read.y == Approx(expected.y).margin(1e-4));
  }
}

TEST_CASE("assign_material_to_all_parts repeats a folder material's maps to size on every part", "[geom]") {
  ObjectAsset asset;
  asset.mesh = two_squares(2.0f, 1.0f);
  asset.materials = {matmaterial::MaterialInputs("square"), matmaterial::MaterialInputs("collapsed")};
  matmaterial::FolderMaterial folder;
  folder.material.set_image(matmaterial::MaterialParameter::Roughness, 0);
  folder.images.push_back(matbase::ImagePixels{"r", 1, 1, 1, {128}});
  folder.tile_size_m = 0.25;
  assign_material_to_all_parts(asset, folder);
  REQUIRE(asset.images.size() == 1);
  CHECK(asset.materials[0].name == "square");
  CHECK(asset.materials[0][matmaterial::MaterialParameter::Roughness].transform.scale == glm::dvec2(8.0));  // 2 m / 0.25 m
  CHECK(asset.materials[1].name == "collapsed");
  CHECK(asset.materials[1][matmaterial::MaterialParameter::Roughness].transform.scale == glm::dvec2(1.0));  // no UV area
}
