#include "matgeom/io/gltf/gltf_writer.h"

#include <filesystem>
#include <stdexcept>

#include <catch2/catch.hpp>

#include "matgeom/io/gltf/gltf_reader.h"
#include "matgeom/mesh_parts.h"
#include "matgeom/tangents.h"
#include "support/temp_dir.h"

// write_gltf against read_gltf (itself tested against hand-assembled files): what is written
// reads back as the same asset, in both containers.

using namespace matgeom;
using P = matmaterial::MaterialParameter;

namespace {

// Two parts that interleave in triangle order, with every attribute, two textured materials.
ObjectAsset two_part_asset() {
  ObjectAsset asset;
  TriangleMesh& mesh = asset.mesh;
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= 3; ++i) {
      const float x = 0.1f * static_cast<float>(i), y = 0.07f * static_cast<float>(j);
      mesh.positions.emplace_back(x, y, 0.3f * x * y + 0.01f * static_cast<float>(i * j));
      mesh.uvs.emplace_back(0.25f * static_cast<float>(i), 0.5f * static_cast<float>(j));
    }
  const auto index = [](int i, int j) { return static_cast<uint32_t>(j * 4 + i); };
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) {
      mesh.triangles.emplace_back(index(i, j), index(i + 1, j), index(i + 1, j + 1));
      mesh.triangles.emplace_back(index(i, j), index(i + 1, j + 1), index(i, j + 1));
      mesh.triangle_parts.insert(mesh.triangle_parts.end(), 2, static_cast<uint32_t>((i + j) % 2));
    }
  compute_vertex_normals(mesh);
  compute_tangents(mesh);
  mesh.part_names = {"wood", "brass handle"};

  matbase::ImagePixels rgb{"rgb.png", 3, 2, 3, {}}, rgba{"rgba.png", 2, 2, 4, {}};
  for (int k = 0; k < 18; ++k) rgb.data.push_back(static_cast<uint8_t>(k * 14));
  for (int k = 0; k < 16; ++k) rgba.data.push_back(static_cast<uint8_t>(255 - k * 13));
  asset.images = {rgb, rgba};

  matmaterial::MaterialInputs wood;
  wood.name = "wood";
  wood.set(P::BaseColor, glm::dvec3(0.5, 0.25, 0.125));
  wood.set_image(P::BaseColor, 0);
  wood.set(P::Metallic, 0.0);
  wood.set(P::Roughness, 0.75);
  wood.normal_image = 1;
  wood.normal_strength = 0.5;
  // Each texture placed on the UVs its own way (KHR_texture_transform).
  wood.normal_transform = {{0.25, -0.5}, 0.75, {2.0, 3.0}};
  // A glow beyond glTF's [0, 1] factor: KHR_materials_emissive_strength carries the rest.
  wood.set(P::Emission, glm::dvec3(0.25, 0.5, 1.0));
  wood.set_image(P::Emission, 0, 0, {{0.0, 0.125}, -1.0, {1.0, 1.0}});
  wood.set(P::EmissionStrength, 2.5);
  // KHR_materials_ior for both: glTF's default is 1.5, the table's (brass) 1.45.
  wood.set(P::Ior, 1.33);
  // Glass where image 0's red says (KHR_materials_transmission).
  wood.set(P::Transmission, 0.5);
  wood.set_image(P::Transmission, 0, 0);
  matmaterial::MaterialInputs brass;
  brass.name = "brass handle";
  brass.set(P::BaseColor, glm::dvec3(1.0, 0.75, 0.25));
  brass.set(P::Metallic, 1.0);
  brass.set(P::Roughness, 0.25);
  brass.set_metallic_roughness_image(1, {{1.5, 0.0}, 0.0, {0.5, 0.25}});
  // Lacquered: the coat from image 0's red, its roughness from image 1's green (glTF's channels).
  brass.set(P::Clearcoat, 0.75);
  brass.set_image(P::Clearcoat, 0, 0);
  brass.set(P::ClearcoatRoughness, 0.125);
  brass.set(P::Alpha, 0.625);  // alphaMode BLEND, baseColorFactor[3]
  brass.set_image(P::ClearcoatRoughness, 1, 1);
  // A velvet (KHR_materials_sheen): its colour from image 0, its width from image 1's alpha, placed.
  brass.set(P::VelvetColor, glm::dvec3(0.5, 0.25, 0.125));
  brass.set_image(P::VelvetColor, 0, 0, {{0.25, 0.0}, 0.5, {2.0, 2.0}});
  brass.set(P::VelvetSigma, 0.375);
  brass.set_image(P::VelvetSigma, 1, 3);
  brass.wrap = matmaterial::TextureWrap::Clamp;
  asset.materials = {wood, brass};
  return asset;
}

void check_same_asset(const ObjectAsset& written, const ObjectAsset& read) {
  // The reader concatenates primitives, one per part, in part order: the merged split.
  const TriangleMesh expected = merge_parts(split_parts(written.mesh));
  const TriangleMesh& mesh = read.mesh;
  REQUIRE(mesh.vertex_count() == expected.vertex_count());
  CHECK(mesh.triangles == expected.triangles);
  CHECK(mesh.triangle_parts == expected.triangle_parts);
  CHECK(mesh.part_names == expected.part_names);
  CHECK(mesh.positions == expected.positions);  // axis swaps and negations are exact
  REQUIRE(mesh.normals.size() == expected.normals.size());
  REQUIRE(mesh.uvs.size() == expected.uvs.size());
  REQUIRE(mesh.tangents.size() == expected.tangents.size());
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    for (int c = 0; c < 3; ++c) {
      CHECK(mesh.normals[v][c] == Approx(expected.normals[v][c]).margin(1e-6));
      CHECK(mesh.tangents[v][c] == Approx(expected.tangents[v][c]).margin(1e-5));
    }
    CHECK(mesh.tangents[v].w == expected.tangents[v].w);
    CHECK(mesh.uvs[v].x == expected.uvs[v].x);
    CHECK(mesh.uvs[v].y == Approx(expected.uvs[v].y).margin(1e-7));  // 1 - (1 - v) rounds
  }

  REQUIRE(read.materials.size() == written.materials.size());
  for (size_t k = 0; k < read.materials.size(); ++k) {
    const matmaterial::MaterialInputs& a = written.materials[k];
    const matmaterial::MaterialInputs& b = read.materials[k];
    CHECK(b.name == a.name);
    CHECK(b.color(P::BaseColor) == a.color(P::BaseColor));
    CHECK(b.scalar(P::Metallic) == a.scalar(P::Metallic));
    CHECK(b.scalar(P::Roughness) == a.scalar(P::Roughness));
    CHECK(b.color(P::Emission) == a.color(P::Emission));
    CHECK(b.scalar(P::EmissionStrength) == a.scalar(P::EmissionStrength));
    CHECK(b.scalar(P::Ior) == a.scalar(P::Ior));
    CHECK(b.scalar(P::Alpha) == a.scalar(P::Alpha));
    CHECK(b.scalar(P::Transmission) == a.scalar(P::Transmission));
    CHECK(b[P::Transmission].channel == a[P::Transmission].channel);
    CHECK(b.scalar(P::Clearcoat) == a.scalar(P::Clearcoat));
    CHECK(b.scalar(P::ClearcoatRoughness) == a.scalar(P::ClearcoatRoughness));
    CHECK(b[P::Clearcoat].channel == a[P::Clearcoat].channel);
    CHECK(b[P::ClearcoatRoughness].channel == a[P::ClearcoatRoughness].channel);
    CHECK(b.color(P::VelvetColor) == a.color(P::VelvetColor));
    // The width is written only with a velvet; without one the reader keeps the table's default.
    if (a.color(P::VelvetColor) != glm::dvec3(0.0)) CHECK(b.scalar(P::VelvetSigma) == a.scalar(P::VelvetSigma));
    CHECK(b[P::VelvetSigma].channel == a[P::VelvetSigma].channel);
    CHECK(b.normal_strength == a.normal_strength);
    CHECK(b.normal_transform == a.normal_transform);
    for (const P p : {P::BaseColor, P::Roughness, P::Metallic, P::Emission, P::Clearcoat, P::ClearcoatRoughness,
                      P::Transmission, P::VelvetColor, P::VelvetSigma})
      CHECK(b[p].transform == a[p].transform);
    CHECK(b.wrap == a.wrap);
    for (const auto& [image_a, image_b] : {std::pair{a[P::BaseColor].image, b[P::BaseColor].image},
                                           std::pair{a[P::Roughness].image, b[P::Roughness].image},
                                           std::pair{a[P::Emission].image, b[P::Emission].image},
                                           std::pair{a[P::Clearcoat].image, b[P::Clearcoat].image},
                                           std::pair{a[P::Transmission].image, b[P::Transmission].image},
                                           std::pair{a[P::ClearcoatRoughness].image, b[P::ClearcoatRoughness].image},
                                           std::pair{a[P::VelvetColor].image, b[P::VelvetColor].image},
                                           std::pair{a[P::VelvetSigma].image, b[P::VelvetSigma].image},
                                           std::pair{a.normal_image, b.normal_image}}) {
      REQUIRE((image_a < 0) == (image_b < 0));
      if (image_a < 0) continue;
      const matbase::ImagePixels& pa = written.images[static_cast<size_t>(image_a)];
      const matbase::ImagePixels& pb = read.images[static_cast<size_t>(image_b)];
      CHECK(pb.width == pa.width);
      CHECK(pb.height == pa.height);
      CHECK(pb.channels == pa.channels);
      CHECK(pb.data == pa.data);  // PNG is lossless
    }
  }
}

}  // namespace

TEST_CASE("write_gltf round-trips through read_gltf as GLB and as glTF", "[geom]") {
  const TempDir dir;
  const ObjectAsset asset = two_part_asset();
  for (const char* name : {"object.glb", "object.gltf"}) {
    INFO(name);
    write_gltf(asset, dir.file(name));
    check_same_asset(asset, read_gltf(dir.file(name)));
  }
  // Nothing but the two files is left behind.
  size_t files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir.path())) ++files;
  CHECK(files == 2);
}

TEST_CASE("write_gltf rejects what glTF cannot hold and leaves nothing behind", "[geom]") {
  const TempDir dir;
  ObjectAsset asset = two_part_asset();
  CHECK_THROWS_AS(write_gltf(asset, dir.file("object.obj")), std::invalid_argument);
  ObjectAsset too_few = asset;
  too_few.materials.pop_back();
  CHECK_THROWS_AS(write_gltf(too_few, dir.file("a.glb")), std::invalid_argument);
  ObjectAsset bad_image = asset;
  bad_image.materials[0].set_image(P::BaseColor, 5);
  CHECK_THROWS_AS(write_gltf(bad_image, dir.file("b.glb")), std::invalid_argument);
  // glTF reads the coat from R; the writer does not repack one channel into another.
  ObjectAsset coat_from_blue = asset;
  coat_from_blue.materials[1].set_image(P::Clearcoat, 0, 2);
  CHECK_THROWS_WITH(write_gltf(coat_from_blue, dir.file("e.glb")),
                    Catch::Matchers::Contains("clearcoat reads image channel 2"));
  // glTF reads the sheen roughness from A.
  ObjectAsset sigma_from_red = asset;
  sigma_from_red.materials[1].set_image(P::VelvetSigma, 1, 0);
  CHECK_THROWS_WITH(write_gltf(sigma_from_red, dir.file("g.glb")),
                    Catch::Matchers::Contains("velvet_sigma reads image channel 0"));
  // glTF keeps opacity only in the base colour's alpha.
  ObjectAsset separate_opacity = asset;
  separate_opacity.materials[0].set_image(P::Alpha, 1, 0);
  CHECK_THROWS_WITH(write_gltf(separate_opacity, dir.file("f.glb")), Catch::Matchers::Contains("opacity"));
  ObjectAsset empty;
  CHECK_THROWS_AS(write_gltf(empty, dir.file("c.glb")), std::invalid_argument);
  CHECK_THROWS_AS(write_gltf(asset, dir.file("missing_dir/d.glb")), std::runtime_error);
  CHECK(std::filesystem::is_empty(dir.path()));
}

namespace {

// The value material input `p` of `desc` reads at texel (x, y) of its image, 0..255.
int input_texel(const ObjectAsset& asset, const matmaterial::MaterialInputs& desc, P p, int x, int y) {
  const matmaterial::MaterialInput& input = desc[p];
  const matbase::ImagePixels& image = asset.images.at(static_cast<size_t>(input.image));
  return matbase::texel_channel(image, static_cast<size_t>(y) * static_cast<size_t>(image.width) + static_cast<size_t>(x),
                       input.channel);
}

}  // namespace

TEST_CASE("write_gltf packs roughness and metallic from any images and channels into glTF's G and B", "[geom]") {
  const TempDir dir;
  ObjectAsset asset = two_part_asset();
  // Roughness from a grey 2x2 image, metallic from the alpha of the 2x2 RGBA image (image 1).
  asset.images.push_back(matbase::ImagePixels{"rough.png", 2, 2, 1, {10, 60, 110, 160}});
  matmaterial::MaterialInputs& brass = asset.materials[1];
  brass.set_image(P::Roughness, 2, 0).set_image(P::Metallic, 1, 3);
  write_gltf(asset, dir.file("packed.glb"));
  const ObjectAsset read = read_gltf(dir.file("packed.glb"));
  const matmaterial::MaterialInputs& back = read.materials[1];
  REQUIRE(back[P::Roughness].image >= 0);
  CHECK(back[P::Roughness].image == back[P::Metallic].image);
  CHECK(back.scalar(P::Roughness) == brass.scalar(P::Roughness));
  CHECK(back.scalar(P::Metallic) == brass.scalar(P::Metallic));
  for (int y = 0; y < 2; ++y) {
    for (int x = 0; x < 2; ++x) {
      CHECK(input_texel(read, back, P::Roughness, x, y) == input_texel(asset, brass, P::Roughness, x, y));
      CHECK(input_texel(read, back, P::Metallic, x, y) == input_texel(asset, brass, P::Metallic, x, y));
    }
  }

  // One input from an image, the other constant: the constant's channel is 255 (a factor of 1).
  brass.set_image(P::Metallic, -1);
  write_gltf(asset, dir.file("roughness_only.glb"));
  const ObjectAsset roughness_only = read_gltf(dir.file("roughness_only.glb"));
  const matmaterial::MaterialInputs& r = roughness_only.materials[1];
  CHECK(input_texel(roughness_only, r, P::Roughness, 1, 1) == 160);
  CHECK(input_texel(roughness_only, r, P::Metallic, 1, 1) == 255);
  CHECK(r.scalar(P::Metallic) == brass.scalar(P::Metallic));
}

TEST_CASE("write_gltf uses an image already in glTF's layout as it is", "[geom]") {
  const TempDir dir;
  const ObjectAsset asset = two_part_asset();  // brass reads G and B of image 1
  write_gltf(asset, dir.file("object.glb"));
  CHECK(read_gltf(dir.file("object.glb")).images.size() == asset.images.size());
}

namespace {

}  // namespace

TEST_CASE("write_gltf refuses inputs glTF reads through one texture but placed apart", "[geom]") {
  const TempDir dir;
  ObjectAsset asset = two_part_asset();
  asset.materials[1][P::Metallic].transform.rotation = 0.5;  // roughness keeps the other placement
  CHECK_THROWS_WITH(write_gltf(asset, dir.file("object.glb")),
                    Catch::Contains("places the images of roughness and metallic differently on the UVs"));
  CHECK(std::filesystem::is_empty(dir.path()));
}
