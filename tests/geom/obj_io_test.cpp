#include "matgeom/io/obj/obj_io.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "support/reader_checks.h"
#include "support/temp_dir.h"
#include "support/test_files.h"

// read_obj against OBJ, MTL and PNG files written here as text and bytes, with expected values
// worked out by hand (OBJ (x, y, z) is Blender (x, -z, y)); write_obj against read_obj.

using namespace matgeom;
using Catch::Matchers::Contains;
using P = matmaterial::MaterialParameter;

namespace {

// The message of the runtime_error read_obj throws, or "" if it throws none.
std::string read_error(const std::string& path) {
  try {
    read_obj(path);
  } catch (const std::runtime_error& error) {
    return error.what();
  }
  return "";
}

// read_obj decodes every texture to RGBA.
std::vector<uint8_t> as_rgba(int channels, const std::vector<uint8_t>& pixels) {
  std::vector<uint8_t> rgba;
  for (size_t i = 0; i < pixels.size(); i += static_cast<size_t>(channels)) {
    for (int c = 0; c < 3; ++c)
      rgba.push_back(pixels[i + static_cast<size_t>(channels > 1 ? c : 0)]);
    rgba.push_back(channels == 4 ? pixels[i + 3] : 255);
  }
  return rgba;
}

void check_vec3(const glm::vec3& actual, const glm::vec3& expected) {
  INFO("actual (" << actual.x << ", " << actual.y << ", " << actual.z << "), expected ("
                  << expected.x << ", " << expected.y << ", " << expected.z << ")");
  CHECK(glm::length(actual - expected) < 1e-6f);
}

void check_color(const glm::dvec3& actual, const glm::dvec3& expected) {
  for (int c = 0; c < 3; ++c) CHECK(actual[c] == Approx(expected[c]).margin(1e-6));
}

// Equal up to the float MTL numbers are read as.
void check_same_transform(const matmaterial::TextureTransform& actual, const matmaterial::TextureTransform& expected) {
  for (int c = 0; c < 2; ++c) {
    CHECK(actual.offset[c] == Approx(expected.offset[c]).margin(1e-6));
    CHECK(actual.scale[c] == Approx(expected.scale[c]).margin(1e-6));
  }
  CHECK(actual.rotation == expected.rotation);
}

// ---- The two-material scene

// Four corners of a quad and a triangle with relative indices that reuses one quad corner with
// a different texture coordinate; a group before any "usemtl" has no material.
const char* kTwoMaterialObj = R"(# two materials
mtllib two.mtl
v 0 0 0
v 1 0 0
v 1 2 0
v 0 1 0
vt 0 0
vt 1 0
vt 1 1
vt 0 1
vt 0.5 0.5
vn 0 0 1
g loose
v 0 0 5
v 1 0 5
v 0 0 4
f 5 6 7
g tiles
usemtl red
f 1/1/1 2/2/1 3/3/1 4/4/1
usemtl blue
v 1 -1 0
f -8/-1/-1 -1/-2/1 2/2/1
)";

const char* kTwoMaterialMtl = R"(newmtl red
Kd 0.8 0.1 0.1
Pr 0.25
Pm 0.75

newmtl unused
Kd 0 1 0

newmtl blue
Kd 0.1 0.2 0.9
Ks 0.4 0.5 0.6
Ns 250
illum 2
)";

}  // namespace

TEST_CASE("OBJ reader: quad, triangle, two materials, a group without one, split vertices",
          "[geom]") {
  TempDir dir;
  write_text(dir.file("two.obj"), kTwoMaterialObj);
  write_text(dir.file("two.mtl"), kTwoMaterialMtl);
  const ObjectAsset asset = read_obj(dir.file("two.obj"));
  const TriangleMesh& mesh = asset.mesh;

  // One vertex per distinct v/vt/vn triple in order of first use: the loose triangle (v5-v7),
  // the quad split by tinyobjloader along its shorter diagonal v2-v4 into (v1 v2 v4) and
  // (v2 v3 v4), then v1 again with vt5 (a new vertex), v8, and v2/vt2/vn1 (reused).
  const std::vector<glm::vec3> positions = {{0, -5, 0}, {1, -5, 0}, {0, -4, 0},
                                            {0, 0, 0},  {1, 0, 0},  {0, 0, 1},
                                            {1, 0, 2},  {0, 0, 0},  {1, 0, -1}};
  const std::vector<glm::vec2> uvs = {{0, 0}, {0, 0}, {0, 0},     {0, 0}, {1, 0},
                                      {0, 1}, {1, 1}, {0.5, 0.5}, {0, 1}};
  REQUIRE(mesh.vertex_count() == positions.size());
  REQUIRE(mesh.uvs.size() == uvs.size());
  for (size_t v = 0; v < positions.size(); ++v) {
    check_vec3(mesh.positions[v], positions[v]);
    CHECK(mesh.uvs[v] == uvs[v]);
    // vn 0 0 1 is Blender's -y; the loose triangle has no normals and gets its face normal.
    check_vec3(mesh.normals[v], v < 3 ? glm::vec3(0, 0, 1) : glm::vec3(0, -1, 0));
  }
  CHECK(mesh.triangles == std::vector<glm::uvec3>{{0, 1, 2}, {3, 4, 5}, {4, 6, 5}, {7, 8, 4}});

  // Parts in MTL order of the used materials, then the faces without one.
  CHECK(mesh.part_names == std::vector<std::string>{"red", "blue", "default"});
  CHECK(mesh.triangle_parts == std::vector<uint32_t>{2, 0, 0, 1});
  REQUIRE(asset.materials.size() == 3);
  const matmaterial::MaterialInputs& red = asset.materials[0];
  CHECK(red.name == "red");
  check_color(red.color(P::BaseColor), {0.8, 0.1, 0.1});
  CHECK(red.scalar(P::Roughness) == Approx(0.25));
  CHECK(red.scalar(P::Metallic) == Approx(0.75));
  CHECK(red.scalar(P::Specular) == 0.0);  // no Ks and no highlights (illum 2): Blender's Specular 0
  const matmaterial::MaterialInputs& blue = asset.materials[1];
  check_color(blue.color(P::BaseColor), {0.1, 0.2, 0.9});
  CHECK(blue.scalar(P::Roughness) == Approx(0.5));  // 1 - sqrt(250 / 1000)
  CHECK(blue.scalar(P::Metallic) == 0.0);
  CHECK(blue.scalar(P::Specular) == Approx(0.5));  // mean of Ks
  const matmaterial::MaterialInputs& none = asset.materials[2];
  CHECK(none.name == "default");
  check_color(none.color(P::BaseColor), glm::dvec3(0.8));
  CHECK(none.scalar(P::Roughness) == 0.5);
  CHECK(none.scalar(P::Metallic) == 0.0);
  for (const matmaterial::MaterialInputs& material : asset.materials) {
    CHECK(material[P::BaseColor].image == -1);
    CHECK(material[P::Roughness].image == -1);
    CHECK(material.normal_image == -1);
  }
  CHECK(asset.images.empty());

  // Tangents for the UVs: unit, perpendicular to the normal. The quad's u runs along +x.
  REQUIRE(mesh.tangents.size() == positions.size());
  for (size_t v = 0; v < positions.size(); ++v) {
    const glm::vec3 t(mesh.tangents[v]);
    CHECK(glm::length(t) == Approx(1.0f).margin(1e-5));
    CHECK(std::abs(glm::dot(t, mesh.normals[v])) < 1e-5f);
  }
  check_vec3(glm::vec3(mesh.tangents[3]), glm::vec3(1, 0, 0));
}

TEST_CASE("OBJ reader maps MTL statements as Blender's importer does", "[geom]") {
  struct Expected {
    const char* name;
    const char* statements;
    glm::dvec3 base_color;
    double roughness, metallic, specular;
  };
  const std::vector<Expected> cases = {
      // Nothing given: Principled's grey, no Ns and no highlights: roughness 1, specular 0.
      {"plain", "", glm::dvec3(0.8), 1.0, 0.0, 0.0},
      // Highlights (illum 2) without Ns or Ks: roughness 0, specular 1.
      {"highlight", "illum 2", glm::dvec3(0.8), 0.0, 0.0, 1.0},
      // Reflection (illum 3..8): metallic is the mean of Ka, 1 without Ka; Ns 1000 is a mirror.
      {"mirror", "illum 3\nKa 0.6 0.3 0.9\nNs 1000", glm::dvec3(0.8), 0.0, 0.6, 0.0},
      {"reflect", "illum 5", glm::dvec3(0.8), 1.0, 1.0, 0.0},
      // illum 9 is glass without reflection: Ka does not make it metallic.
      {"glass", "illum 9\nKa 1 1 1", glm::dvec3(0.8), 1.0, 0.0, 0.0},
      // Pr and Pm replace what Ns and Ka give.
      {"pbr", "illum 3\nKa 0.9 0.9 0.9\nNs 0\nPr 0.3\nPm 0.2", glm::dvec3(0.8), 0.3, 0.2, 0.0},
      // Ns beyond 1000 (the spec's "normal" range) counts as 1000, as in Blender.
      {"shiny", "Ns 4000", glm::dvec3(0.8), 0.0, 0.0, 0.0},
      // The bounds of [0, 1] themselves, and a colour of one number: a grey (the MTL spec).
      {"bounds", "Kd 1 0 1\nKs 1 1 1\nPr 1\nPm 0\nillum 4", {1.0, 0.0, 1.0}, 1.0, 0.0, 1.0},
      {"grey", "Kd 0.25", glm::dvec3(0.25), 1.0, 0.0, 0.0},
  };
  std::string obj = "mtllib cases.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n";
  std::string mtl;
  for (const Expected& expected : cases) {
    obj += std::string("usemtl ") + expected.name + "\nf 1 2 3\n";
    mtl += std::string("newmtl ") + expected.name + "\n" + expected.statements + "\n";
  }
  TempDir dir;
  write_text(dir.file("cases.obj"), obj);
  write_text(dir.file("cases.mtl"), mtl);
  const ObjectAsset asset = read_obj(dir.file("cases.obj"));
  REQUIRE(asset.materials.size() == cases.size());
  for (size_t k = 0; k < cases.size(); ++k) {
    const matmaterial::MaterialInputs& material = asset.materials[k];
    INFO("material " << cases[k].name);
    CHECK(material.name == cases[k].name);
    check_color(material.color(P::BaseColor), cases[k].base_color);
    CHECK(material.scalar(P::Roughness) == Approx(cases[k].roughness).margin(1e-6));
    CHECK(material.scalar(P::Metallic) == Approx(cases[k].metallic).margin(1e-6));
    CHECK(material.scalar(P::Specular) == Approx(cases[k].specular).margin(1e-6));
  }
}

TEST_CASE("OBJ reader maps Ni, d, Ke, Tf, Pc, Pcr and Ps as Blender 3.4's importer does", "[geom]") {
  // The expected values are those Blender 3.4.1's OBJ importer (File > Import > Wavefront, the
  // C++ one) put into the Principled inputs for these two materials: Pc is the Clearcoat input
  // itself (no factor 0.25 in 3.4), Tr is ignored (d, absent, keeps alpha 1), Tf's mean is the
  // transmission.
  TempDir dir;
  write_text(dir.file("pbr.obj"), "mtllib pbr.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                  "usemtl lacquer\nf 1 2 3\nusemtl glass\nf 3 2 1\nusemtl bright\nf 1 3 2\n");
  write_text(dir.file("pbr.mtl"),
             "newmtl lacquer\nKd 0.5 0.4 0.3\nNs 250\nNi 1.33\nd 0.6\nKe 0.2 0.1 0.05\nPc 0.8\nPcr 0.2\n"
             "Ps 0.7\nillum 2\n"
             "newmtl glass\nKd 0.5 0.4 0.3\nNi 1.6\nTf 0.9 0.9 0.9\nTr 0.25\nillum 7\n"
             "newmtl bright\nKe 4 2 1\n");
  const ObjectAsset asset = read_obj(dir.file("pbr.obj"));
  REQUIRE(asset.materials.size() == 3);
  // Ke beyond 1 (Blender: that colour at strength 1): the same radiance as colour x strength.
  check_color(asset.materials[2].color(P::Emission), {1.0, 0.5, 0.25});
  CHECK(asset.materials[2].scalar(P::EmissionStrength) == 4.0);
  const matmaterial::MaterialInputs& lacquer = asset.materials[0];
  CHECK(lacquer.scalar(P::Specular) == 1.0);
  CHECK(lacquer.scalar(P::Roughness) == Approx(0.5));
  CHECK(lacquer.scalar(P::Ior) == Approx(1.33));
  CHECK(lacquer.scalar(P::Alpha) == Approx(0.6));
  check_color(lacquer.color(P::Emission), {0.2, 0.1, 0.05});
  CHECK(lacquer.scalar(P::EmissionStrength) == 1.0);
  CHECK(lacquer.scalar(P::Clearcoat) == Approx(0.8));
  CHECK(lacquer.scalar(P::ClearcoatRoughness) == Approx(0.2));
  CHECK(lacquer.scalar(P::Sheen) == Approx(0.7));
  CHECK(lacquer.scalar(P::Transmission) == 0.0);
  const matmaterial::MaterialInputs& glass = asset.materials[1];
  CHECK(glass.scalar(P::Metallic) == 1.0);
  CHECK(glass.scalar(P::Specular) == 0.0);
  CHECK(glass.scalar(P::Roughness) == 1.0);
  CHECK(glass.scalar(P::Ior) == Approx(1.6));
  CHECK(glass.scalar(P::Transmission) == Approx(0.9));
  CHECK(glass.scalar(P::Alpha) == 1.0);
  check_color(glass.color(P::Emission), glm::dvec3(0.0));
  CHECK(glass.scalar(P::Clearcoat) == 0.0);
  CHECK(glass.scalar(P::ClearcoatRoughness) == Approx(0.03));
  CHECK(glass.scalar(P::Sheen) == 0.0);
}

TEST_CASE("OBJ reader reads map_Ke as the emission and map_d's alpha as the opacity", "[geom]") {
  TempDir dir;
  const std::vector<uint8_t> rgba = {255, 128, 0, 64, 0, 0, 255, 255};
  write_bytes(dir.file("glow.png"), encode_png(2, 1, 4, rgba));
  write_text(dir.file("maps.obj"), "mtllib maps.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                                   "usemtl maps\nf 1/1 2/2 3/3\n");
  write_text(dir.file("maps.mtl"), "newmtl maps\nKe 0.5 0.5 0.5\nmap_Ke glow.png\nmap_d glow.png\n");
  const ObjectAsset asset = read_obj(dir.file("maps.obj"));
  REQUIRE(asset.images.size() == 1);  // decoded once for both
  const matmaterial::MaterialInputs& maps = asset.materials[0];
  CHECK(maps[P::Emission].image == 0);
  check_color(maps.color(P::Emission), glm::dvec3(1.0));  // the map replaces Ke
  CHECK(maps.scalar(P::EmissionStrength) == 1.0);
  CHECK(maps[P::Alpha].image == 0);
  CHECK(maps[P::Alpha].channel == 3);  // Blender links the image's Alpha output
  CHECK(maps.scalar(P::Alpha) == 1.0);
}

TEST_CASE("OBJ reader decodes map_Kd, packs map_Pr into G and reads map_Bump and norm", "[geom]") {
  TempDir dir;
  const std::vector<uint8_t> colors = {255, 0, 0, 0, 255, 0, 0, 0, 255, 10, 20, 30};
  const std::vector<uint8_t> rough = {0, 64, 128, 255};
  const std::vector<uint8_t> normal = {128, 128, 255};
  write_bytes(dir.file("colors.png"), encode_png(2, 2, 3, colors));
  write_bytes(dir.file("rough.png"), encode_png(2, 2, 1, rough));
  write_bytes(dir.file("normal map.png"), encode_png(1, 1, 3, normal));
  write_text(dir.file("textured.obj"),
             "mtllib textured.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
             "usemtl textured\nf 1/1 2/2 3/3\nusemtl shares\nf 3/3 2/2 1/1\n");
  write_text(dir.file("textured.mtl"),
             "newmtl textured\nKd 0.2 0.3 0.4\nmap_Kd colors.png\nmap_Pr rough.png\nPm 0.4\n"
             "map_Bump -bm 0.7 normal map.png\n"
             "newmtl shares\nmap_Kd \"colors.png\"\nnorm -bm 0.5 normal map.png\n");
  const ObjectAsset asset = read_obj(dir.file("textured.obj"));

  REQUIRE(asset.images.size() == 3);  // colors.png and the normal map are decoded once
  const matbase::ImagePixels& base = asset.images[0];
  CHECK(base.name == "colors.png");
  CHECK(base.width == 2);
  CHECK(base.height == 2);
  CHECK(base.channels == 4);
  CHECK(base.data == as_rgba(3, colors));
  // Roughness in G, metallic B = 255 so that the factor Pm stands; R unused.
  const matbase::ImagePixels& packed = asset.images[1];
  CHECK(packed.channels == 3);
  CHECK(packed.data == std::vector<uint8_t>{0, 0, 255, 0, 64, 255, 0, 128, 255, 0, 255, 255});
  CHECK(asset.images[2].data == as_rgba(3, normal));

  const matmaterial::MaterialInputs& textured = asset.materials[0];
  // A map replaces its value in Blender: the base colour and roughness factors are 1.
  CHECK(textured[P::BaseColor].image == 0);
  check_color(textured.color(P::BaseColor), glm::dvec3(1.0));
  CHECK(textured[P::Roughness].image == 1);
  CHECK(textured.scalar(P::Roughness) == 1.0);
  CHECK(textured.scalar(P::Metallic) == Approx(0.4));
  CHECK(textured.normal_image == 2);
  CHECK(textured.normal_strength == Approx(0.7));
  CHECK(textured.wrap == matmaterial::TextureWrap::Repeat);
  const matmaterial::MaterialInputs& shares = asset.materials[1];
  CHECK(shares[P::BaseColor].image == 0);  // the quotes are dropped, as Blender drops them
  CHECK(shares[P::Roughness].image == -1);
  CHECK(shares.normal_image == 2);
  CHECK(shares.normal_strength == Approx(0.5));
}

namespace {

// Where a map looks its image up at `uv`, as the renderer does (matmaterial/texture_transform.h).
void check_lookup(const matmaterial::TextureTransform& transform, glm::vec2 uv, glm::vec2 expected) {
  const glm::vec2 looked_up = matmaterial::uv_affine(transform).apply(uv);
  INFO("uv (" << uv.x << ", " << uv.y << ") looked up at (" << looked_up.x << ", " << looked_up.y << "), expected ("
              << expected.x << ", " << expected.y << ")");
  CHECK(glm::length(looked_up - expected) < 1e-5f);
}

}  // namespace

TEST_CASE("OBJ reader places every map by -o and -s as Blender's Mapping node does: uv' = s uv + o",
          "[geom]") {
  TempDir dir;
  write_bytes(dir.file("t.png"), encode_png(1, 1, 3, {10, 20, 30}));
  write_text(dir.file("placed.obj"), "mtllib placed.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                                     "usemtl placed\nf 1/1 2/2 3/3\nusemtl plain\nf 3/3 2/2 1/1\n");
  // Options in either order, w ignored, v and w filled in (-s 4 is -s 4 1 1, -o 0.5 is -o 0.5 0 0).
  write_text(dir.file("placed.mtl"),
             "newmtl placed\nmap_Kd -s 2 3 1 -o 0.25 0.5 0 t.png\nmap_Ke -o 0.5 t.png\nmap_d -s -1 1 7 t.png\n"
             "map_Pr -s 4 t.png\nmap_Pm -o 0 0 0 -s 1 1 1 t.png\nmap_Bump -bm 0.5 -s 0.5 0.25 -o 0.1 0.2 0.3 t.png\n"
             "newmtl plain\nmap_Kd t.png\nnorm -o -1 -2 -3 -s 3 3 3 t.png\n");
  const ObjectAsset asset = read_obj(dir.file("placed.obj"));
  REQUIRE(asset.images.size() == 2);  // t.png, and t.png packed as roughness and metallic
  const matmaterial::MaterialInputs& placed = asset.materials[0];
  // s (2, 3), o (0.25, 0.5): (0.1, 0.2) -> (0.2 + 0.25, 0.6 + 0.5).
  check_lookup(placed[P::BaseColor].transform, {0.1f, 0.2f}, {0.45f, 1.1f});
  check_lookup(placed[P::BaseColor].transform, {0.0f, 0.0f}, {0.25f, 0.5f});
  check_lookup(placed[P::BaseColor].transform, {1.0f, 1.0f}, {2.25f, 3.5f});
  check_lookup(placed[P::Emission].transform, {0.1f, 0.2f}, {0.6f, 0.2f});
  check_lookup(placed[P::Emission].transform, {1.0f, 1.0f}, {1.5f, 1.0f});
  check_lookup(placed[P::Alpha].transform, {0.1f, 0.2f}, {-0.1f, 0.2f});  // mirrored in u
  check_lookup(placed[P::Alpha].transform, {1.0f, 1.0f}, {-1.0f, 1.0f});
  // The packed image's two inputs keep their own placements.
  CHECK(placed[P::Roughness].image == placed[P::Metallic].image);
  check_lookup(placed[P::Roughness].transform, {0.1f, 0.2f}, {0.4f, 0.2f});
  check_lookup(placed[P::Roughness].transform, {1.0f, 1.0f}, {4.0f, 1.0f});
  CHECK(placed[P::Metallic].transform.is_identity());
  // s (0.5, 0.25), o (0.1, 0.2): (0.1, 0.2) -> (0.05 + 0.1, 0.05 + 0.2).
  check_lookup(placed.normal_transform, {0.1f, 0.2f}, {0.15f, 0.25f});
  check_lookup(placed.normal_transform, {1.0f, 1.0f}, {0.6f, 0.45f});
  CHECK(placed.normal_strength == 0.5);
  const matmaterial::MaterialInputs& plain = asset.materials[1];
  CHECK(plain[P::BaseColor].transform.is_identity());
  check_lookup(plain.normal_transform, {0.1f, 0.2f}, {-0.7f, -1.4f});
  check_lookup(plain.normal_transform, {1.0f, 1.0f}, {2.0f, 1.0f});

  SECTION("a scale tinyobjloader's float cannot hold is refused naming the map") {
    write_text(dir.file("placed.mtl"), "newmtl placed\nmap_Kd -s 1e-50 1 1 t.png\nnewmtl plain\n");
    CHECK_THAT(read_error(dir.file("placed.obj")),
               Contains(dir.file("placed.mtl") + ": material \"placed\" map_Kd: -o 0 0 -s 0 1 cannot place a texture"));
  }
}

TEST_CASE("OBJ reader makes parts from material slots or from groups", "[geom]") {
  TempDir dir;
  write_text(dir.file("groups.obj"),
             "mtllib groups.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
             "f 1 2 3\n"
             "g first\nusemtl a\nf 1 2 3\nusemtl b\nf 1 3 4\n"
             "o  second \nf 2 3 4\n"
             "g first\nusemtl a\nf 1 2 4\n");
  // Names are trimmed, as Blender trims them.
  write_text(dir.file("groups.mtl"), "newmtl a\nKd 1 0 0\nnewmtl \t b \nKd 0 0 1\n");

  const ObjectAsset by_material = read_obj(dir.file("groups.obj"));
  CHECK(by_material.mesh.part_names == std::vector<std::string>{"a", "b", "default"});
  CHECK(by_material.mesh.triangle_parts == std::vector<uint32_t>{2, 0, 1, 1, 0});

  ObjReadOptions options;
  options.parts_from = ObjReadOptions::PartsFrom::Group;
  const ObjectAsset by_group = read_obj(dir.file("groups.obj"), options);
  // Groups ("g" or "o") in file order; faces before any are unnamed; a repeated name is the
  // same part.
  CHECK(by_group.mesh.part_names == std::vector<std::string>{"default", "first", "second"});
  CHECK(by_group.mesh.triangle_parts == std::vector<uint32_t>{0, 1, 1, 2, 1});
  // A group's material is that of its first face; "second" continues with b.
  REQUIRE(by_group.materials.size() == 3);
  CHECK(by_group.materials[0].name == "default");
  CHECK(by_group.materials[1].name == "a");
  check_color(by_group.materials[1].color(P::BaseColor), {1, 0, 0});
  CHECK(by_group.materials[2].name == "b");
  check_color(by_group.materials[2].color(P::BaseColor), {0, 0, 1});
  CHECK(by_group.mesh.positions == by_material.mesh.positions);
  CHECK(by_group.mesh.triangles == by_material.mesh.triangles);
}

namespace {

// Two parts whose triangles come part after part and whose vertices are numbered in order of
// first use, which is the order read_obj numbers them in; values that need all nine digits.
ObjectAsset round_trip_asset() {
  ObjectAsset asset;
  TriangleMesh& mesh = asset.mesh;
  mesh.positions = {{0.1f, -2.5e-3f, 12345.678f}, {1.0f / 3.0f, 7e-8f, -1.0f},
                    {-0.0f, 1e30f, 2.0f / 7.0f},  {3.14159274f, -1e-20f, 0.5f},
                    {-123.456f, 0.7f, 0.3f},      {9.99999975e-6f, 6.0f, -7.25f}};
  mesh.uvs = {{0.3f, 0.7f}, {2.5f, -0.25f},       {1.0f / 3.0f, 0.1f},
              {0.0f, 1.0f}, {0.99999994f, 1e-7f}, {-3.0f, 4.5f}};
  for (const glm::vec3& direction :
       {glm::vec3(1, 2, 3), glm::vec3(0, 0, 1), glm::vec3(-1, 0.5f, 0),
        glm::vec3(0.3f, -0.4f, 0.5f), glm::vec3(0, -1, 0), glm::vec3(2, 2, -1)}) {
    mesh.normals.push_back(glm::normalize(direction));
  }
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}, {4, 5, 1}};
  mesh.triangle_parts = {0, 0, 1};
  mesh.part_names = {"red_paint", "blue"};

  matbase::ImagePixels base{"base.png", 2, 1, 4, {1, 2, 3, 4, 250, 251, 252, 253}};
  matbase::ImagePixels metallic_roughness{"mr.png", 2, 1, 3, {0, 100, 200, 0, 50, 25}};
  matbase::ImagePixels normal{"normal.png", 1, 1, 4, {128, 128, 255, 255}};
  asset.images = {base, metallic_roughness, normal};

  matmaterial::MaterialInputs red = matmaterial::MaterialInputs("red_paint");
  red.set_image(P::BaseColor, 0);
  red.set(P::BaseColor, glm::dvec3(1.0));
  red.set_metallic_roughness_image(1);
  // Placements in glTF's terms, written as -o and -s; metallic and roughness placed apart.
  red[P::BaseColor].transform = matmaterial::TextureTransform{{0.25, -0.5}, 0.0, {2.0, 3.0}};
  red[P::Roughness].transform = matmaterial::TextureTransform{{-0.75, 0.125}, 0.0, {-1.5, 0.5}};
  red.set(P::Roughness, 1.0);
  red.set(P::Metallic, 1.0);
  red.set(P::Specular, 0.25);
  matmaterial::MaterialInputs blue = matmaterial::MaterialInputs("blue");
  blue.set(P::BaseColor, glm::dvec3(0.1, 0.2, 0.9));
  blue.set(P::Roughness, 0.8);
  blue.set(P::Metallic, 0.2);
  blue.set(P::Specular, 0.5);
  blue.normal_image = 2;
  blue.normal_strength = 0.75;
  blue.normal_transform = matmaterial::TextureTransform{{0.0, 0.0}, 0.0, {4.0, 4.0}};
  // The inputs beyond the classic statements: Ni, d, Ke (beyond 1: colour x strength), Tf, Pc,
  // Pcr, Ps.
  blue.set(P::Ior, 1.33);
  blue.set(P::Alpha, 0.5);
  blue.set(P::Emission, glm::dvec3(1.0, 0.5, 0.25));
  blue.set(P::EmissionStrength, 2.0);
  blue.set(P::Transmission, 0.25);
  blue.set(P::Clearcoat, 0.75);
  blue.set(P::ClearcoatRoughness, 0.125);
  blue.set(P::Sheen, 0.5);
  asset.materials = {red, blue};
  return asset;
}

}  // namespace

TEST_CASE("OBJ written by write_obj reads back as the same asset", "[geom]") {
  TempDir dir;
  const ObjectAsset original = round_trip_asset();
  const std::string path = dir.file("round trip.obj");
  write_obj(original, path);

  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path())) {
    files.push_back(entry.path().filename().string());
  }
  std::sort(files.begin(), files.end());
  CHECK(files == std::vector<std::string>{"round trip.mtl", "round trip.obj",
                                          "round trip_image0.png", "round trip_image1_metallic.png",
                                          "round trip_image1_roughness.png",
                                          "round trip_image2.png"});

  // Placements as -o u (1 - sy - oy) 0 -s sx sy 1, worked out by hand from round_trip_asset's.
  const std::string mtl = read_bytes(dir.file("round trip.mtl"));
  CHECK_THAT(mtl, Contains("\nmap_Kd -o 0.25 -1.5 0 -s 2 3 1 round trip_image0.png\n"));
  CHECK_THAT(mtl, Contains("\nmap_Pr -o -0.75 0.375 0 -s -1.5 0.5 1 round trip_image1_roughness.png\n"));
  CHECK_THAT(mtl, Contains("\nmap_Pm round trip_image1_metallic.png\n"));
  CHECK_THAT(mtl, Contains("\nmap_Bump -bm 0.75 -o 0 -3 0 -s 4 4 1 round trip_image2.png\n"));

  const ObjectAsset read = read_obj(path);
  const TriangleMesh& mesh = read.mesh;
  CHECK(mesh.positions == original.mesh.positions);
  CHECK(mesh.uvs == original.mesh.uvs);
  CHECK(mesh.normals == original.mesh.normals);
  CHECK(mesh.triangles == original.mesh.triangles);
  CHECK(mesh.triangle_parts == original.mesh.triangle_parts);
  CHECK(mesh.part_names == original.mesh.part_names);
  CHECK(mesh.tangents.size() == mesh.vertex_count());

  REQUIRE(read.materials.size() == 2);
  for (size_t k = 0; k < 2; ++k) {
    const matmaterial::MaterialInputs& expected = original.materials[k];
    const matmaterial::MaterialInputs& actual = read.materials[k];
    INFO("material " << expected.name);
    CHECK(actual.name == expected.name);
    check_color(actual.color(P::BaseColor), expected.color(P::BaseColor));
    CHECK(actual.scalar(P::Roughness) == Approx(expected.scalar(P::Roughness)));
    for (const P p : {P::Ior, P::Alpha, P::Transmission, P::Clearcoat, P::Sheen})
      CHECK(actual.scalar(p) == Approx(expected.scalar(p)));
    if (expected.scalar(P::Clearcoat) != 0.0)
      CHECK(actual.scalar(P::ClearcoatRoughness) == Approx(expected.scalar(P::ClearcoatRoughness)));
    // MTL holds only the emitted radiance.
    check_color(actual.color(P::Emission) * actual.scalar(P::EmissionStrength),
                expected.color(P::Emission) * expected.scalar(P::EmissionStrength));
    CHECK(actual.scalar(P::Metallic) == Approx(expected.scalar(P::Metallic)));
    CHECK(actual.scalar(P::Specular) == Approx(expected.scalar(P::Specular)));
    CHECK(actual.normal_strength == Approx(expected.normal_strength));
    CHECK(actual[P::BaseColor].image == expected[P::BaseColor].image);
    CHECK(actual[P::Roughness].image == expected[P::Roughness].image);
    CHECK(actual.normal_image == expected.normal_image);
    for (const P p : {P::BaseColor, P::Roughness, P::Metallic})
      check_same_transform(actual[p].transform, expected[p].transform);
    check_same_transform(actual.normal_transform, expected.normal_transform);
  }
  REQUIRE(read.images.size() == 3);
  CHECK(read.images[0].data == original.images[0].data);
  // Written as a grey map_Pr (G) and map_Pm (B) and packed again; R is not kept.
  CHECK(read.images[1].data == std::vector<uint8_t>{0, 100, 200, 0, 50, 25});
  CHECK(read.images[2].data == original.images[2].data);
}

TEST_CASE("write_obj makes names OBJ-safe and unique and refuses what it cannot write", "[geom]") {
  TempDir dir;
  ObjectAsset asset = round_trip_asset();
  asset.images.clear();
  asset.materials[0] = matmaterial::MaterialInputs("two words\nand a line");
  asset.materials[1] = matmaterial::MaterialInputs("two_words_and_a_line");
  asset.mesh.part_names = {"", "group one"};
  write_obj(asset, dir.file("names.obj"));
  const std::string obj = read_bytes(dir.file("names.obj"));
  CHECK_THAT(obj, Contains("mtllib names.mtl\n"));
  CHECK_THAT(obj, Contains("g two_words_and_a_line\nusemtl two_words_and_a_line\n"));
  CHECK_THAT(obj, Contains("g group_one\nusemtl two_words_and_a_line_2\n"));
  CHECK_THAT(obj, Contains("\nf 1/1/1 2/2/2 3/3/3\n"));
  ObjReadOptions by_group;
  by_group.parts_from = ObjReadOptions::PartsFrom::Group;
  CHECK(read_obj(dir.file("names.obj"), by_group).mesh.part_names ==
        std::vector<std::string>{"two_words_and_a_line", "group_one"});

  SECTION("fewer materials than parts") {
    asset.materials.pop_back();
    CHECK_THROWS_AS(write_obj(asset, dir.file("short.obj")), std::invalid_argument);
  }
  SECTION("a texture placement -o and -s cannot say, or read_obj would refuse") {
    asset.images = round_trip_asset().images;
    asset.materials[0].set_image(P::BaseColor, 0, 0, matmaterial::TextureTransform{{0.0, 0.0}, 0.5, {1.0, 1.0}});
    CHECK_THROWS_WITH(write_obj(asset, dir.file("rotated.obj")), Contains("rotates its base_color texture"));
    asset.materials[0].set_image(P::BaseColor, 0, 0, matmaterial::TextureTransform{{0.0, 0.0}, 0.0, {1.0, 0.0}});
    CHECK_THROWS_WITH(write_obj(asset, dir.file("flat.obj")), Contains("a scale of 0"));
  }
  SECTION("an image index out of range") {
    asset.materials[1].normal_image = 3;
    CHECK_THROWS_AS(write_obj(asset, dir.file("image.obj")), std::invalid_argument);
  }
  SECTION("a failed write throws naming the path and leaves nothing behind") {
    // The .obj cannot be renamed over a directory (after its images and .mtl were), and nothing
    // can be written into a missing directory.
    const std::string taken = dir.file("taken.obj");
    std::filesystem::create_directories(taken + "/inside");
    for (const std::string& path : {taken, dir.file("missing directory/object.obj")}) {
      try {
        write_obj(round_trip_asset(), path);
        FAIL("write_obj did not throw");
      } catch (const std::runtime_error& error) {
        CHECK_THAT(error.what(), Contains(path));
      }
    }
    for (const auto& entry : std::filesystem::directory_iterator(dir.path())) {
      const std::string name = entry.path().filename().string();
      CHECK((name == "taken.obj" || name.rfind("names", 0) == 0));
    }
  }
}

TEST_CASE("OBJ reader errors name the file and the problem", "[geom]") {
  TempDir dir;
  const std::string path = dir.file("broken.obj");
  const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

  SECTION("missing file") {
    CHECK_THAT(read_error(path), Contains(path + ": ") && Contains("no such file"));
  }
  SECTION("index out of range") {
    // Past the end in a triangle, before the start through a relative index, past the end in a
    // quad (which tinyobjloader drops with a warning) and past the texture coordinates.
    for (const char* face : {"f 1 2 7\n", "f -5 1 2\n", "f 1 2 3 9\n", "vt 0 0\nf 1/2 2/1 3/1\n"}) {
      write_text(path, triangle + face);
      INFO(face);
      CHECK_THAT(read_error(path), Contains(path + ": ") && Contains("out of range"));
    }
  }
  SECTION("NaN and infinite vertices") {
    // tinyobjloader reads 0e999 as 0 x inf = NaN; 1e999 is infinite, 1e39 beyond its float.
    write_text(path, triangle + "v 0e999 0 0\nf 1 2 3\n");
    CHECK_THAT(read_error(path), Contains(path + ": ") && Contains("non-finite position 4"));
    for (const char* vertex : {"v 0 1e999 0\n", "vn 0 0 -1e999\n", "vt 1e39 0\n"}) {
      write_text(path, triangle + vertex + "f 1 2 3\n");
      INFO(vertex);
      CHECK_THAT(read_error(path), Contains(path + ": line 4: ") && Contains("is not a finite number"));
    }
  }
  SECTION("words tinyobjloader would silently read as 0") {
    // nan, inf, a decimal comma and a stray word: each used to give a vertex coordinate of 0.
    for (const char* vertex : {"v 1 nan 0\n", "v inf 0 0\n", "vt 0,5 1\n", "vn 0 0 up\n", "v 1 2 3e\n"}) {
      write_text(path, triangle + vertex + "f 1 2 3\n");
      INFO(vertex);
      CHECK_THAT(read_error(path), Contains(path + ": line 4: ") && Contains("is not a finite number"));
    }
    // Signs, exponents, leading dots and trailing comments are numbers (OBJ's +Y up becomes +Z).
    write_text(path, "v -1 +0.5 .25e+1\nv 1E-3 0 0 # comment\nv 0 1. 0\nf 1 2 3\n");
    CHECK(read_obj(path).mesh.positions[0] == glm::vec3(-1.0f, -2.5f, 0.5f));
  }
  SECTION("zero faces") {
    for (const std::string& text : {triangle, triangle + "f 1 1 2\nl 1 2\n"}) {
      write_text(path, text);
      CHECK_THAT(read_error(path), Contains(path + ": ") && Contains("no faces"));
    }
  }
  SECTION("a face index 0, which OBJ does not have") {
    write_text(path, triangle + "f 0 1 2\n");
    const std::string error = read_error(path);
    CHECK_THAT(error, Contains(path + ": face index 0: indices count from 1, or back from -1 (line 4, corner \"0\")"));
    CHECK_THAT(error, !Contains("tinyobjloader") && !Contains("zero value"));
  }
  SECTION("missing .mtl") {
    write_text(path, "mtllib nowhere.mtl\n" + triangle + "f 1 2 3\n");
    CHECK_THAT(read_error(path), Contains(path + ": ") && Contains("material library") &&
                                     Contains(dir.file("nowhere.mtl")));
  }
  SECTION("missing or broken texture") {
    write_text(path, "mtllib broken.mtl\n" + triangle + "usemtl m\nf 1 2 3\n");
    write_text(dir.file("broken.mtl"), "newmtl m\nmap_Kd lost.png\n");
    CHECK_THAT(read_error(path), Contains(path + ": ") && Contains(dir.file("broken.mtl")) &&
                                     Contains("texture \"lost.png\" not found (looked at " + dir.file("lost.png")));
    write_text(dir.file("lost.png"), "not a PNG");
    CHECK_THAT(read_error(path), Contains(path + ": ") && Contains("lost.png: cannot decode the image"));
  }
  SECTION("map_Pr and map_Pm of different sizes") {
    write_text(path, "mtllib sizes.mtl\n" + triangle + "usemtl m\nf 1 2 3\n");
    write_text(dir.file("sizes.mtl"), "newmtl m\nmap_Pr a.png\nmap_Pm b.png\n");
    write_bytes(dir.file("a.png"), encode_png(1, 1, 1, {7}));
    write_bytes(dir.file("b.png"), encode_png(2, 1, 1, {7, 8}));
    CHECK_THAT(read_error(path), Contains(path + ": ") && Contains("differ in size"));
  }
  SECTION("a polygon too large for tinyobjloader's triangulation") {
    std::string text = triangle + "f";
    for (int corner = 0; corner < 10001; ++corner) text += " " + std::to_string(corner % 3 + 1);
    write_text(path, text + "\n");
    CHECK_THAT(read_error(path), Contains(path + ": ") && Contains("corners"));
  }
}

TEST_CASE("OBJ statements are checked where they are written, indices reported as written", "[geom]") {
  TempDir dir;
  const std::string path = dir.file("shape.obj");
  const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  // Each statement on line 4, after the triangle's vertices, and what the error says about it.
  for (const auto& [statement, problem] : {
           std::pair{"v 1 2\n", "line 4: a 'v' line takes x y z (and w, or r g b); this one has 2 numbers"},
           std::pair{"vn 0 1\n", "line 4: a 'vn' line takes x y z; this one has 2 numbers"},
           std::pair{"f 1 2\n", "line 4: a 'f' line needs 3 or more corners; this one has 2"},
           // tinyobjloader's atoi wraps 99999999999 to 1215752191: the text as written is reported.
           std::pair{"f 1 2 99999999999\n", "face index out of range: position 99999999999 but the file has 3 "
                                            "before this line (line 4, corner \"99999999999\")"},
           std::pair{"f 1 2 -4\n", "face index out of range: position -4 but the file has 3 before this line (line 4"},
           std::pair{"f 1//1 2 3\n", "face index out of range: normal 1 but the file has 0 before this line (line 4, "
                                     "corner \"1//1\")"},
           std::pair{"f 1/x 2 3\n", "face index \"x\" is not a whole number (line 4, corner \"1/x\")"},
           std::pair{"f 1.5 2 3\n", "face index \"1.5\" is not a whole number (line 4, corner \"1.5\")"},
           std::pair{"f 1/1/1/1 2 3\n", "a face corner is v, v/vt, v//vn or v/vt/vn (line 4, corner \"1/1/1/1\")"},
           std::pair{"l 1 0\n", "line index 0: indices count from 1, or back from -1 (line 4, corner \"0\")"},
       }) {
    write_text(path, triangle + statement);
    INFO(statement);
    const std::string error = read_error(path);
    CHECK_THAT(error, Contains(path + ": " + problem));
    CHECK_THAT(error, !Contains("1215752191") && !Contains("tinyobjloader"));
  }
  // A later vertex does not count for an earlier face; a comment after the corners is no index.
  write_text(path, "v 0 0 0\nv 1 0 0\nf 1 2 3\nv 0 1 0\n");
  CHECK_THAT(read_error(path), Contains(path + ": face index out of range: position 3 but the file has 2 before this "
                                               "line (line 3, corner \"3\")"));
  write_text(path, triangle + "f 1 2 3 # the only face\nv 1 2 3 1\nvt 0.5\n");
  CHECK(read_obj(path).mesh.triangle_count() == 1);
}

TEST_CASE("OBJ reader refuses a usemtl naming no material, at its line", "[geom]") {
  TempDir dir;
  const std::string path = dir.file("used.obj");
  write_text(dir.file("used.mtl"), "newmtl wood\nKd 0.5 0.4 0.3\nnewmtl steel\nPm 1\n");
  const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  write_text(path, "mtllib used.mtl\n" + triangle + "usemtl wood\nf 1 2 3\nusemtl stone\nf 1 3 2\n");
  CHECK_THAT(read_error(path), Contains(path + ": line 7: usemtl \"stone\": no such material (its material "
                                               "libraries define \"wood\", \"steel\")"));
  // tinyobjloader reads a library when it meets its mtllib, so a usemtl before it finds nothing.
  write_text(path, triangle + "usemtl wood\nf 1 2 3\nmtllib used.mtl\n");
  CHECK_THAT(read_error(path), Contains(path + ": line 4: usemtl \"wood\": no such material (its material "
                                               "library is named by an \"mtllib\" after this line)"));
  write_text(dir.file("empty.mtl"), "# nothing\n");
  write_text(path, "mtllib empty.mtl\n" + triangle + "usemtl wood\nf 1 2 3\n");
  CHECK_THAT(read_error(path), Contains(path + ": line 5: usemtl \"wood\": no such material (no material "
                                               "library defines any material)"));
  // Without any mtllib (an OBJ exported without its .mtl) the faces take the default material.
  write_text(path, triangle + "usemtl wood\nf 1 2 3\n");
  CHECK(read_obj(path).mesh.triangle_count() == 1);
}

TEST_CASE("MTL numbers are checked where they are written, against the range their parameter can use",
          "[geom]") {
  TempDir dir;
  const std::string obj = dir.file("checked.obj");
  const std::string mtl = dir.file("checked.mtl");
  write_text(obj, "mtllib checked.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m\nf 1 2 3\n");
  write_bytes(dir.file("t.png"), encode_png(1, 1, 1, {7}));
  // Each statement on line 2 of material m, and what the error says about it (the ranges are the
  // parameter table's: colours, roughness, metallic, opacity, clearcoat and sheen in [0, 1], IOR in
  // [1, 1000], emission strength up to 10^6).
  for (const auto& [statement, problem] : {
           // tinyobjloader read each of these words as 0.
           std::pair{"Kd nan 0 0", "Kd: \"nan\" is not a finite number"},
           std::pair{"Kd red 0.2 0.2", "Kd: \"red\" is not a finite number"},
           std::pair{"Kd 0.5 inf 0", "Kd: \"inf\" is not a finite number"},
           std::pair{"Kd 0.5 0.5 1e39", "Kd: \"1e39\" is not a finite number"},
           // A negative component replaced the whole colour by the default grey; 5 was clamped to 1.
           std::pair{"Kd -0.5 0.2 0.2", "Kd: \"-0.5\" is outside [0, 1]"},
           std::pair{"Kd 5", "Kd: \"5\" is outside [0, 1]"},
           std::pair{"Kd 0.5 0.5", "Kd takes 3 numbers (or 1 for a grey); it has 2"},
           std::pair{"Ka 0.2 0.2 -1.2", "Ka: \"-1.2\" is outside [0, ...)"},
           std::pair{"Ks 3 3 3", "Ks: \"3\" is outside [0, 1]"},
           std::pair{"Tf 0.5 x 0.5", "Tf: \"x\" is not a finite number"},
           std::pair{"Ke -1 0 0", "Ke: \"-1\" is outside [0, 1000000]"},
           std::pair{"Ns -5", "Ns: \"-5\" is outside [0, ...)"},
           std::pair{"Ns 100 200", "Ns takes 1 number; it has 2"},
           std::pair{"Ni 1001", "Ni: \"1001\" is outside [0, 1000]"},
           std::pair{"Ni -0.5", "Ni: \"-0.5\" is outside [0, 1000]"},
           std::pair{"d 1.5", "d: \"1.5\" is outside [0, 1]"},
           std::pair{"Tr -0.1", "Tr: \"-0.1\" is outside [0, 1]"},
           std::pair{"Pr 1.5", "Pr: \"1.5\" is outside [0, 1]"},
           std::pair{"Pm -0.5", "Pm: \"-0.5\" is outside [0, 1]"},
           std::pair{"Pc 2", "Pc: \"2\" is outside [0, 1]"},
           std::pair{"Pcr nan", "Pcr: \"nan\" is not a finite number"},
           std::pair{"Ps shiny", "Ps: \"shiny\" is not a finite number"},
           std::pair{"illum 2.5", "illum: \"2.5\" is not a whole number"},
           std::pair{"illum 11", "illum: \"11\" is outside [0, 10]"},
           // Map options: numbers checked the same way, words among their choices.
           std::pair{"map_Bump -bm -1 t.png", "map_Bump -bm: \"-1\" is outside [0, ...)"},
           std::pair{"map_Kd -bm t.png", "map_Kd -bm: \"t.png\" is not a finite number"},
           std::pair{"map_Kd -o nan t.png", "map_Kd -o: \"nan\" is not a finite number"},
           std::pair{"map_Kd -s 2 0 t.png", "map_Kd -s: \"0\" scales the texture to nothing (v must not be 0)"},
           std::pair{"norm -s -0 t.png", "norm -s: \"-0\" scales the texture to nothing (u must not be 0)"},
           std::pair{"map_Kd -o 0 1e39 t.png", "map_Kd -o: \"1e39\" is not a finite number"},
           std::pair{"map_Kd -mm", "map_Kd -mm needs 1 or 2 numbers"},
           std::pair{"map_Kd -clamp maybe t.png", "map_Kd -clamp takes one of on, off; not \"maybe\""},
           std::pair{"map_Kd -texres 0 t.png", "map_Kd -texres: \"0\" is outside [1, 2147483647]"},
           std::pair{"map_Kd -imfchan q t.png", "map_Kd -imfchan takes one of r, g, b, m, l, z; not \"q\""},
           std::pair{"map_Kd -zoom 2 t.png", "map_Kd: unknown option \"-zoom\""},
           std::pair{"map_Kd", "map_Kd: no file name"},
       }) {
    write_text(mtl, std::string("newmtl m\n") + statement + "\n");
    INFO(statement);
    CHECK_THAT(read_error(obj), Contains(obj + ": " + mtl + ": line 2: " + problem));
  }
  // Ka beyond 1 reads where it shades nothing (illum 2), and is refused as illum 3's metallic.
  write_text(mtl, "newmtl m\nKa 1.5 1.5 1.5\nillum 2\n");
  CHECK(read_obj(obj).materials[0].scalar(P::Metallic) == 0.0);
  write_text(mtl, "newmtl m\nKa 1.5 1.5 1.5\nillum 3\n");
  CHECK_THAT(read_error(obj), Contains(obj + ": " + mtl + ": material \"m\": Ka's mean 1.5 is the metallic of illum 3, which must be from 0 to 1"));
  // Ni 0, which exporters write for "unset", reads on an opaque material (the IOR shades only
  // glass) and is refused on one that transmits.
  write_text(mtl, "newmtl m\nNi 0\n");
  CHECK(read_obj(obj).materials[0].scalar(P::Ior) == 1.0);
  write_text(mtl, "newmtl m\nNi 0.5\nTf 1 1 1\n");
  CHECK_THAT(read_error(obj), Contains(obj + ": " + mtl + ": material \"m\": Ni 0.5 with transmission 1: glass needs an IOR from 1 to 1000"));
  // A file name after fewer than three numbers of -s: tinyobjloader would take it as the third.
  write_text(mtl, "newmtl m\nmap_Kd -s 1 1 t.png\nmap_Bump -bm 0.5 -o 0 t.png\n");
  const ObjectAsset asset = read_obj(obj);
  REQUIRE(asset.images.size() == 1);
  CHECK(asset.materials[0][P::BaseColor].image == 0);
  CHECK(asset.materials[0].normal_image == 0);
  CHECK(asset.materials[0].normal_strength == 0.5);
  write_text(mtl, "Kd 1 1 1\nnewmtl\n");
  CHECK_THAT(read_error(obj), Contains(obj + ": " + mtl + ": line 2: newmtl without a material name"));
}

TEST_CASE("OBJ textures in formats not read, or damaged, are named as such", "[geom]") {
  TempDir dir;
  const std::string obj = dir.file("textured.obj");
  write_text(obj, "mtllib textured.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m\nf 1 2 3\n");
  write_text(dir.file("textured.mtl"), "newmtl m\nmap_Kd texture.img\n");
  const std::string texture = dir.file("texture.img");
  // An OpenEXR file starts with its magic number and version 2; stb_image called it "Unknown image format".
  write_bytes(texture, std::string("\x76\x2f\x31\x01" "\x02\x00\x00\x00" "channels", 16));
  std::string error = read_error(obj);
  CHECK_THAT(error, Contains(obj + ": ") && Contains(texture + ": cannot decode the image: an OpenEXR image; images are "
                                                               "read from PNG, JPEG, BMP or TGA files"));
  CHECK_THAT(error, !Contains("Unknown image format") && !Contains("STB"));
  std::vector<uint8_t> png = encode_png(4, 4, 3, std::vector<uint8_t>(48, 90));
  png.resize(png.size() - 30);  // the image data cut short
  write_bytes(texture, png);
  error = read_error(obj);
  CHECK_THAT(error, Contains(texture + ": cannot decode the image: the PNG data is damaged or cut short"));
  CHECK_THAT(error, !Contains("Unknown image format") && !Contains("STB"));
  write_text(texture, "plain text");
  CHECK_THAT(read_error(obj), Contains(texture + ": cannot decode the image: not an image in a format read here"));
}

TEST_CASE("OBJ reader ignores the tags and skin weights tinyobjloader mishandles", "[geom]") {
  // Unscreened, these 2000 tag lines would make tinyobjloader allocate about 600 MB per shape,
  // and the skin weight's joint 1e40 would overflow its conversion to int.
  TempDir dir;
  std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvw 1 1e40 0.5\n";
  for (int line = 0; line < 2000; ++line) text += "t crease 8192/8192/8192\n";
  for (int shape = 0; shape < 3; ++shape) text += "o shape" + std::to_string(shape) + "\nf 1 2 3\n";
  write_text(dir.file("tags.obj"), text);
  CHECK(read_obj(dir.file("tags.obj")).mesh.triangle_count() == 3);
}

namespace {

const char* kFuzzObj = R"(mtllib fuzz.mtl
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0.5 0.5 1e-3
vt 0 0
vt 1 0
vt 1 1
vn 0 0 1
g body
usemtl shiny
f 1/1/1 2/2/1 3/3/1 4/1/1
s 1
o lid
usemtl matte
f -1//-1 -2//1 -3//1
f 1 2 5 3 4
l 1 2
)";

const char* kFuzzMtl = R"(newmtl shiny
Kd 0.5 0.25 0.125
Ns 96
Pr 0.4
illum 2
newmtl matte
Ka 0.2 0.2 0.2
Pm 0.1
illum 3
map_Kd -s 1 1 1 tex.png
map_Bump -bm 2 tex.png
)";

// Checks one variant of the fuzz files: an .obj text with the base .mtl, or the base .obj with
// an .mtl text. Each variant goes to new files, removed afterwards: rewriting a file in place
// makes ext4 flush it at every close (auto_da_alloc), a hundred times slower.
class FuzzVariants {
 public:
  explicit FuzzVariants(const TempDir& dir) : dir_(dir) {
    write_bytes(dir_.file("tex.png"), encode_png(1, 1, 3, {1, 2, 3}));
    write_text(dir_.file("fuzz.mtl"), kFuzzMtl);
  }

  void check_obj(const std::string& obj) {
    const std::string path = dir_.file("variant" + std::to_string(++count_) + ".obj");
    write_text(path, obj);
    check_reads_or_rejects(path, [](const std::string& file) { return read_obj(file); });
    std::filesystem::remove(path);
  }

  void check_mtl(const std::string& mtl) {
    const std::string name = "variant" + std::to_string(++count_);
    std::string obj = kFuzzObj;
    obj.replace(obj.find("fuzz.mtl"), 8, name + ".mtl");
    write_text(dir_.file(name + ".mtl"), mtl);
    check_obj(obj);
    std::filesystem::remove(dir_.file(name + ".mtl"));
  }

 private:
  const TempDir& dir_;
  int count_ = 0;
};

}  // namespace

TEST_CASE("OBJ reader survives truncated and mutated files", "[geom]") {
  TempDir dir;
  FuzzVariants variants(dir);
  const std::string obj = kFuzzObj;
  const std::string mtl = kFuzzMtl;
  write_text(dir.file("fuzz.obj"), obj);
  REQUIRE(read_obj(dir.file("fuzz.obj")).mesh.triangle_count() == 6);

  for (size_t length = 0; length < obj.size(); ++length) variants.check_obj(obj.substr(0, length));
  for (size_t length = 0; length < mtl.size(); ++length) variants.check_mtl(mtl.substr(0, length));

  // Single-byte mutations, every fourth in the .mtl: a flipped bit, or a byte the number and
  // index parsers react to.
  std::mt19937 generator(20240611u);
  const std::string replacements = "0123456789-+/.eE \t\n";
  for (int mutation = 0; mutation < 3000; ++mutation) {
    const bool in_mtl = mutation % 4 == 3;
    std::string text = in_mtl ? mtl : obj;
    const size_t at = std::uniform_int_distribution<size_t>(0, text.size() - 1)(generator);
    if (mutation % 2 == 0) {
      text[at] = static_cast<char>(text[at] ^ (1 << (generator() % 8)));
    } else {
      text[at] = replacements[generator() % replacements.size()];
    }
    if (in_mtl) {
      variants.check_mtl(text);
    } else {
      variants.check_obj(text);
    }
  }
}
