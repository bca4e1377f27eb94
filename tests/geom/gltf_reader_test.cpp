#include "matgeom/io/gltf/gltf_reader.h"
#include "matgeom/shading_normals.h"
#include "matgeom/tangents.h"

#include <unistd.h>

#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "support/reader_checks.h"
#include "support/temp_dir.h"
#include "support/test_files.h"

// These tests write real glTF files byte by byte (JSON, binary buffers, PNG images, the GLB
// container) and check what the reader makes of them against values computed here.

namespace fs = std::filesystem;
using json = nlohmann::json;
using P = matmaterial::MaterialParameter;

namespace {

constexpr int kUnsignedByte = 5121;
constexpr int kUnsignedShort = 5123;
constexpr int kUnsignedInt = 5125;
constexpr int kFloat = 5126;
constexpr int kClampToEdge = 33071;
constexpr int kModePoints = 0;
constexpr int kModeTriangleStrip = 5;

std::string base64(const std::vector<uint8_t>& bytes) {
  static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const uint32_t b0 = bytes[i];
    const uint32_t b1 = i + 1 < bytes.size() ? bytes[i + 1] : 0;
    const uint32_t b2 = i + 2 < bytes.size() ? bytes[i + 2] : 0;
    const uint32_t triple = (b0 << 16) | (b1 << 8) | b2;
    out += alphabet[(triple >> 18) & 63];
    out += alphabet[(triple >> 12) & 63];
    out += i + 1 < bytes.size() ? alphabet[(triple >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? alphabet[triple & 63] : '=';
  }
  return out;
}

// ---- glTF writer

enum class Container { EmbeddedDataUri, ExternalFiles, Glb };

class GltfWriter {
 public:
  GltfWriter(const TempDir& dir, std::string stem, Container container)
      : dir_(dir), stem_(std::move(stem)), container_(container) {
    doc_["asset"]["version"] = "2.0";
  }

  json& doc() { return doc_; }

  int add_view(const void* data, size_t size, size_t stride = 0) {
    while (bin_.size() % 4 != 0) bin_.push_back(0);
    json view = {{"buffer", 0}, {"byteOffset", bin_.size()}, {"byteLength", size}};
    if (stride != 0) view["byteStride"] = stride;
    const uint8_t* bytes = static_cast<const uint8_t*>(data);
    bin_.insert(bin_.end(), bytes, bytes + size);
    return append(doc_["bufferViews"], view);
  }

  int add_accessor(int view, int component_type, size_t count, const char* type,
                   size_t byte_offset = 0, bool normalized = false) {
    json accessor = {
        {"bufferView", view}, {"componentType", component_type}, {"count", count}, {"type", type}};
    if (byte_offset != 0) accessor["byteOffset"] = byte_offset;
    if (normalized) accessor["normalized"] = true;
    return append(doc_["accessors"], accessor);
  }

  template <typename T>
  int add_data(const std::vector<T>& values, int component_type, const char* type, int components) {
    const int view = add_view(values.data(), values.size() * sizeof(T));
    return add_accessor(view, component_type, values.size() / static_cast<size_t>(components),
                        type);
  }

  int add_vec3(const std::vector<float>& values) { return add_data(values, kFloat, "VEC3", 3); }
  int add_vec2(const std::vector<float>& values) { return add_data(values, kFloat, "VEC2", 2); }

  int add_image(const std::vector<uint8_t>& png, const std::string& name) {
    json image;
    switch (container_) {
      case Container::EmbeddedDataUri:
        image["uri"] = "data:image/png;base64," + base64(png);
        break;
      case Container::ExternalFiles:
        write_bytes(dir_.file(name), png);
        image["uri"] = name;
        break;
      case Container::Glb:
        image["bufferView"] = add_view(png.data(), png.size());
        image["mimeType"] = "image/png";
        break;
    }
    return append(doc_["images"], image);
  }

  // Writes the file and returns its path.
  std::string write() {
    while (bin_.size() % 4 != 0) bin_.push_back(0);
    if (!bin_.empty()) doc_["buffers"] = json::array({{{"byteLength", bin_.size()}}});
    if (container_ == Container::Glb) return write_glb();
    if (!bin_.empty()) {
      if (container_ == Container::EmbeddedDataUri) {
        doc_["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(bin_);
      } else {
        write_bytes(dir_.file(stem_ + ".bin"), bin_);
        doc_["buffers"][0]["uri"] = stem_ + ".bin";
      }
    }
    const std::string path = dir_.file(stem_ + ".gltf");
    write_text(path, doc_.dump(1));
    return path;
  }

 private:
  static int append(json& array, const json& item) {
    if (array.is_null()) array = json::array();
    array.push_back(item);
    return static_cast<int>(array.size()) - 1;
  }

  static void put_le32(std::vector<uint8_t>& out, uint32_t value) {
    for (int shift = 0; shift < 32; shift += 8) out.push_back(static_cast<uint8_t>(value >> shift));
  }

  std::string write_glb() {
    std::string text = doc_.dump();
    while (text.size() % 4 != 0) text += ' ';
    std::vector<uint8_t> glb = {'g', 'l', 'T', 'F'};
    put_le32(glb, 2);
    put_le32(glb,
             static_cast<uint32_t>(12 + 8 + text.size() + (bin_.empty() ? 0 : 8 + bin_.size())));
    put_le32(glb, static_cast<uint32_t>(text.size()));
    put_le32(glb, 0x4E4F534Au);  // "JSON"
    glb.insert(glb.end(), text.begin(), text.end());
    if (!bin_.empty()) {
      put_le32(glb, static_cast<uint32_t>(bin_.size()));
      put_le32(glb, 0x004E4942u);  // "BIN\0"
      glb.insert(glb.end(), bin_.begin(), bin_.end());
    }
    const std::string path = dir_.file(stem_ + ".glb");
    write_bytes(path, glb);
    return path;
  }

  const TempDir& dir_;
  std::string stem_;
  Container container_;
  json doc_;
  std::vector<uint8_t> bin_;
};

// glTF (+Y up) to Blender (+Z up), written out independently of the reader.
glm::dvec3 to_blender(const glm::dvec3& p) { return {p.x, -p.z, p.y}; }

glm::dvec3 transform_point(const glm::dmat4& m, const glm::dvec3& p) {
  return glm::dvec3(m * glm::dvec4(p, 1.0));
}

void check_near(const glm::vec3& actual, const glm::dvec3& expected, double margin = 1e-5) {
  INFO("actual (" << actual.x << ", " << actual.y << ", " << actual.z << "), expected ("
                  << expected.x << ", " << expected.y << ", " << expected.z << ")");
  CHECK(glm::length(glm::dvec3(actual) - expected) < margin);
}

glm::dvec3 face_normal(const matgeom::TriangleMesh& mesh, const glm::uvec3& t) {
  const glm::dvec3 a(mesh.positions[t[0]]), b(mesh.positions[t[1]]), c(mesh.positions[t[2]]);
  return glm::normalize(glm::cross(b - a, c - a));
}

// The message of the runtime_error read_gltf throws, or "" if it throws none.
std::string read_error(const std::string& path) {
  try {
    matgeom::read_gltf(path);
  } catch (const std::runtime_error& error) {
    return error.what();
  }
  return "";
}

// ---- The two-material quad scene

// Quad corners in glTF space, a unit square in the xy plane facing +z, and their glTF UVs
// (v down: the image's top-left corner is uv (0, 0)).
const std::vector<float> kQuadPositions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
const std::vector<float> kQuadNormals = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
const std::vector<float> kQuadUvs = {0.0f, 1.0f, 1.0f, 1.0f, 1.0f, 0.25f, 0.0f, 0.0f};

// Parent node: TRS with a rotation of 30 degrees about a tilted axis; child node: a matrix.
const glm::dvec3 kParentTranslation(1.0, 2.0, 3.0);
const glm::dvec3 kParentAxis = glm::normalize(glm::dvec3(1.0, 2.0, 2.0));
const double kParentAngle = glm::radians(30.0);
const glm::dvec3 kParentScale(2.0, 0.5, 1.5);
const glm::dvec3 kChildTranslation(0.5, 0.0, -1.0);
const glm::dvec3 kChildScale(1.0, 3.0, 1.0);

glm::dmat4 expected_world_transform() {
  glm::dmat4 parent = glm::translate(glm::dmat4(1.0), kParentTranslation);
  parent = glm::rotate(parent, kParentAngle, kParentAxis);
  parent = glm::scale(parent, kParentScale);
  const glm::dmat4 child =
      glm::scale(glm::translate(glm::dmat4(1.0), kChildTranslation), kChildScale);
  return parent * child;
}

// 8-bit 2x2 base colour image (rows top to bottom) and a 16-bit 2x1 image.
const std::vector<uint16_t> kBaseColorPixels = {255, 0, 0, 0, 255, 0, 0, 0, 255, 10, 20, 30};
const std::vector<uint16_t> kSixteenBitPixels = {0, 65535, 32896, 1000, 257, 65280};

std::string write_two_material_quad(const TempDir& dir, Container container) {
  GltfWriter writer(dir, "quad", container);
  const int positions = writer.add_vec3(kQuadPositions);
  const int normals = writer.add_vec3(kQuadNormals);
  const int uvs = writer.add_vec2(kQuadUvs);
  const int indices_u8 = writer.add_data(std::vector<uint8_t>{0, 1, 2}, kUnsignedByte, "SCALAR", 1);
  const int indices_u16 =
      writer.add_data(std::vector<uint16_t>{0, 2, 3}, kUnsignedShort, "SCALAR", 1);
  const json attributes = {{"POSITION", positions}, {"NORMAL", normals}, {"TEXCOORD_0", uvs}};

  json& doc = writer.doc();
  doc["meshes"] = json::array(
      {{{"primitives",
         json::array({{{"attributes", attributes}, {"indices", indices_u8}, {"material", 1}},
                      {{"attributes", attributes}, {"indices", indices_u16}, {"material", 0}}})}}});

  const double half = 0.5 * kParentAngle;
  const glm::dvec3 q = std::sin(half) * kParentAxis;
  // Column-major, as glTF stores matrices: the translation is the last column.
  const json child_matrix = {kChildScale.x,       0.0,                 0.0,                 0.0,  //
                             0.0,                 kChildScale.y,       0.0,                 0.0,  //
                             0.0,                 0.0,                 kChildScale.z,       0.0,  //
                             kChildTranslation.x, kChildTranslation.y, kChildTranslation.z, 1.0};
  doc["nodes"] = json::array(
      {{{"name", "parent"},
        {"translation", {kParentTranslation.x, kParentTranslation.y, kParentTranslation.z}},
        {"rotation", {q.x, q.y, q.z, std::cos(half)}},
        {"scale", {kParentScale.x, kParentScale.y, kParentScale.z}},
        {"children", {1}}},
       {{"name", "child"}, {"mesh", 0}, {"matrix", child_matrix}}});
  doc["scenes"] = json::array({{{"nodes", {0}}}});
  doc["scene"] = 0;

  const int base_image = writer.add_image(encode_png(2, 2, 3, 8, kBaseColorPixels), "base.png");
  const int wide_image = writer.add_image(encode_png(2, 1, 3, 16, kSixteenBitPixels), "wide.png");
  doc["samplers"] =
      json::array({{{"wrapS", kClampToEdge}, {"wrapT", kClampToEdge}}, json::object()});
  doc["textures"] = json::array(
      {{{"source", base_image}, {"sampler", 0}}, {{"source", wide_image}, {"sampler", 1}}});
  doc["materials"] = json::array({{{"name", "red_metal"},
                                   {"pbrMetallicRoughness",
                                    {{"baseColorFactor", {0.8, 0.1, 0.1, 1.0}},
                                     {"metallicFactor", 0.9},
                                     {"roughnessFactor", 0.3},
                                     {"baseColorTexture", {{"index", 0}}}}},
                                   {"normalTexture", {{"index", 1}, {"scale", 0.7}}},
                                   {"alphaMode", "BLEND"},
                                   {"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 0.4}}}}}},
                                  {{"name", "blue"},
                                   {"alphaMode", "MASK"},
                                   {"alphaCutoff", 0.3},
                                   {"pbrMetallicRoughness",
                                    {{"baseColorFactor", {0.1, 0.2, 0.9, 0.5}},
                                     {"metallicFactor", 0.0},
                                     {"roughnessFactor", 0.6},
                                     {"metallicRoughnessTexture", {{"index", 1}}}}},
                                   // A lacquer from the red channel, its roughness left out (glTF's 0).
                                   {"extensions",
                                    {{"KHR_materials_clearcoat",
                                      {{"clearcoatFactor", 0.6}, {"clearcoatTexture", {{"index", 1}}}}},
                                     // A transmission texture under a factor of 0: no glass (Blender's importer).
                                     {"KHR_materials_transmission", {{"transmissionTexture", {{"index", 0}}}}},
                                     // Cloth sheen, its colour under a texture, its roughness from another's alpha.
                                     {"KHR_materials_sheen",
                                      {{"sheenColorFactor", {0.5, 0.25, 1.0}},
                                       {"sheenColorTexture", {{"index", 0}}},
                                       {"sheenRoughnessFactor", 0.4},
                                       {"sheenRoughnessTexture", {{"index", 1}}}}}}}}});
  doc["extensionsUsed"] =
      json::array({"KHR_materials_clearcoat", "KHR_materials_transmission", "KHR_materials_sheen"});
  return writer.write();
}

}  // namespace

TEST_CASE("glTF two-material quad: transforms, axes, uvs, parts, materials, images", "[geom]") {
  const Container container =
      GENERATE(Container::EmbeddedDataUri, Container::ExternalFiles, Container::Glb);
  TempDir dir;
  const std::string path = write_two_material_quad(dir, container);
  INFO("file " << path);
  const matgeom::ObjectAsset asset = matgeom::read_gltf(path);
  const matgeom::TriangleMesh& mesh = asset.mesh;

  // Parts follow the glTF material order: part 0 = material 0 (second primitive).
  REQUIRE(mesh.triangle_count() == 2);
  REQUIRE(mesh.part_names == std::vector<std::string>{"red_metal", "blue"});
  REQUIRE(mesh.triangle_parts.size() == 2);
  REQUIRE(mesh.normals.size() == mesh.vertex_count());
  REQUIRE(mesh.uvs.size() == mesh.vertex_count());
  REQUIRE(mesh.tangents.size() == mesh.vertex_count());

  const glm::dmat4 world = expected_world_transform();
  const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(glm::dmat3(world)));
  for (size_t t = 0; t < 2; ++t) {
    const glm::uvec3 triangle = mesh.triangles[t];
    const uint32_t part = mesh.triangle_parts[t];
    const std::array<int, 3> corners =
        part == 1 ? std::array<int, 3>{0, 1, 2} : std::array<int, 3>{0, 2, 3};
    for (int k = 0; k < 3; ++k) {
      const int c = corners[static_cast<size_t>(k)];
      const glm::dvec3 p(kQuadPositions[3 * c], kQuadPositions[3 * c + 1],
                         kQuadPositions[3 * c + 2]);
      check_near(mesh.positions[triangle[k]], to_blender(transform_point(world, p)));
      const glm::dvec3 n = glm::normalize(normal_matrix * glm::dvec3(0, 0, 1));
      check_near(mesh.normals[triangle[k]], to_blender(n));
      const glm::vec2 uv = mesh.uvs[triangle[k]];
      CHECK(uv.x == Approx(kQuadUvs[2 * c]));
      CHECK(uv.y == Approx(1.0 - kQuadUvs[2 * c + 1]));
      const glm::vec4 tangent = mesh.tangents[triangle[k]];
      CHECK(std::abs(glm::dot(glm::vec3(tangent), mesh.normals[triangle[k]])) < 1e-5);
      CHECK(tangent.w == 1.0f);
    }
    // The winding still agrees with the normals (positive determinant: no flip).
    CHECK(glm::dot(face_normal(mesh, triangle), glm::dvec3(mesh.normals[triangle[0]])) > 0.999);
  }

  REQUIRE(asset.materials.size() == 2);
  const matmaterial::MaterialInputs& red = asset.materials[0];
  CHECK(red.name == "red_metal");
  CHECK(red.color(P::BaseColor).r == Approx(0.8));
  CHECK(red.color(P::BaseColor).g == Approx(0.1));
  CHECK(red.color(P::BaseColor).b == Approx(0.1));
  CHECK(red.scalar(P::Metallic) == Approx(0.9));
  CHECK(red.scalar(P::Roughness) == Approx(0.3));
  CHECK(red[P::Roughness].image == -1);
  CHECK(red.normal_strength == Approx(0.7));
  CHECK(red.wrap == matmaterial::TextureWrap::Clamp);
  // Without the clearcoat extension Blender's defaults stay: no coat, coat roughness 0.03.
  CHECK(red.scalar(P::Clearcoat) == 0.0);
  CHECK(red.scalar(P::ClearcoatRoughness) == Approx(0.03));
  // Blender's importer gives every glTF material glTF's IOR 1.5, not the node's 1.45.
  CHECK(red.scalar(P::Ior) == 1.5);
  CHECK(red.scalar(P::Transmission) == Approx(0.4));
  // BLEND: opacity = baseColorFactor[3] x the base texture's alpha.
  CHECK(red.scalar(P::Alpha) == 1.0);
  CHECK(red[P::Alpha].image == red[P::BaseColor].image);
  CHECK(red[P::Alpha].channel == 3);
  CHECK(red[P::Transmission].image == -1);
  CHECK(red[P::Clearcoat].image == -1);
  // Without the sheen extension no velvet is added.
  CHECK(red.color(P::VelvetColor) == glm::dvec3(0.0));
  CHECK(red[P::VelvetColor].image == -1);
  const matmaterial::MaterialInputs& blue = asset.materials[1];
  CHECK(blue.name == "blue");
  CHECK(blue.color(P::BaseColor).b == Approx(0.9));
  CHECK(blue.scalar(P::Metallic) == 0.0);
  CHECK(blue.scalar(P::Roughness) == Approx(0.6));
  CHECK(blue[P::BaseColor].image == -1);
  CHECK(blue.normal_image == -1);
  CHECK(blue.wrap == matmaterial::TextureWrap::Repeat);
  // Blender's importer: Clearcoat = factor x texture R, Clearcoat Roughness = its factor, 0 when absent.
  CHECK(blue.scalar(P::Clearcoat) == Approx(0.6));
  CHECK(blue[P::Clearcoat].channel == 0);
  CHECK(blue.scalar(P::ClearcoatRoughness) == 0.0);
  CHECK(blue[P::ClearcoatRoughness].image == -1);
  CHECK(blue.scalar(P::Transmission) == 0.0);
  // MASK as Blender 3.4 renders it in Cycles: the cutoff is ignored, the alpha kept.
  CHECK(blue.scalar(P::Alpha) == Approx(0.5));
  CHECK(blue[P::Alpha].image == -1);
  CHECK(blue[P::Transmission].image == -1);
  // Blender's importer: a Velvet BSDF of Color = sheenColorFactor x texture RGB, Sigma =
  // sheenRoughnessFactor x texture A.
  CHECK(blue.color(P::VelvetColor) == glm::dvec3(0.5, 0.25, 1.0));
  CHECK(blue[P::VelvetColor].image == red[P::BaseColor].image);
  CHECK(blue[P::VelvetColor].channel == 0);
  CHECK(blue.scalar(P::VelvetSigma) == Approx(0.4));
  CHECK(blue[P::VelvetSigma].image == red.normal_image);
  CHECK(blue[P::VelvetSigma].channel == 3);
  // One image used by two materials (and by the coat) is stored once.
  CHECK(blue[P::Roughness].image == red.normal_image);
  CHECK(blue[P::Clearcoat].image == red.normal_image);

  REQUIRE(asset.images.size() == 2);
  REQUIRE(red[P::BaseColor].image >= 0);
  const matbase::ImagePixels& base = asset.images[static_cast<size_t>(red[P::BaseColor].image)];
  CHECK(base.width == 2);
  CHECK(base.height == 2);
  CHECK(base.channels == 3);
  CHECK(base.data == std::vector<uint8_t>(kBaseColorPixels.begin(), kBaseColorPixels.end()));
  const matbase::ImagePixels& wide = asset.images[static_cast<size_t>(red.normal_image)];
  CHECK(wide.width == 2);
  CHECK(wide.height == 1);
  CHECK(wide.data == std::vector<uint8_t>{0, 255, 128, 4, 1, 254});
  if (container == Container::ExternalFiles) {
    CHECK(base.name == "base.png");
  } else {
    CHECK(base.name.rfind("quad.gl", 0) == 0);
    CHECK(base.name.find("#image0") != std::string::npos);
  }
}

TEST_CASE("glTF interleaved, normalized and non-indexed data under a mirroring node", "[geom]") {
  TempDir dir;
  GltfWriter writer(dir, "mirrored", Container::ExternalFiles);
  // Two triangles without indices; each vertex is 3 floats of position then two normalized
  // 16-bit texture coordinates, 16 bytes apart.
  struct Vertex {
    float position[3];
    uint16_t uv[2];
  };
  const std::vector<Vertex> vertices = {{{0, 0, 0}, {0, 65535}},     {{2, 0, 0}, {65535, 65535}},
                                        {{2, 1, 0}, {65535, 32768}}, {{0, 0, 0}, {0, 65535}},
                                        {{2, 1, 0}, {65535, 32768}}, {{0, 1, 0}, {0, 32768}}};
  static_assert(sizeof(Vertex) == 16, "interleaved layout");
  const int view =
      writer.add_view(vertices.data(), vertices.size() * sizeof(Vertex), sizeof(Vertex));
  const int positions = writer.add_accessor(view, kFloat, vertices.size(), "VEC3");
  const int uvs = writer.add_accessor(view, kUnsignedShort, vertices.size(), "VEC2", 12, true);
  json& doc = writer.doc();
  doc["meshes"] = json::array(
      {{{"primitives",
         json::array({{{"attributes", {{"POSITION", positions}, {"TEXCOORD_0", uvs}}}}})}}});
  doc["nodes"] = json::array({{{"mesh", 0}, {"scale", {-1.0, 1.0, 1.0}}}});
  doc["scenes"] = json::array({{{"nodes", {0}}}});
  doc["scene"] = 0;
  const std::string path = writer.write();

  const matgeom::ObjectAsset asset = matgeom::read_gltf(path);
  const matgeom::TriangleMesh& mesh = asset.mesh;
  REQUIRE(mesh.triangle_count() == 2);
  REQUIRE(mesh.vertex_count() == 6);
  // No material: one default part.
  CHECK(mesh.part_names == std::vector<std::string>{"default"});
  REQUIRE(asset.materials.size() == 1);
  CHECK(asset.materials[0].scalar(P::Metallic) == 0.0);

  // Without NORMAL the faces are flat (glTF 2.0 requires it): no vertex normals, so no tangents.
  CHECK(mesh.normals.empty());
  CHECK(mesh.tangents.empty());
  // Flat shading made explicit, as the renderer does for a normal map, gives each corner the
  // re-wound face's normal and a tangent frame on it.
  matgeom::TriangleMesh flat = matgeom::flat_shaded(mesh);
  matgeom::compute_tangents(flat);
  for (size_t v = 0; v < 6; ++v) {
    const Vertex& in = vertices[v];
    const glm::dvec3 mirrored(-in.position[0], in.position[1], in.position[2]);
    check_near(mesh.positions[v], to_blender(mirrored));
    CHECK(mesh.uvs[v].x == Approx(in.uv[0] / 65535.0));
    CHECK(mesh.uvs[v].y == Approx(1.0 - in.uv[1] / 65535.0));
    // The mirrored quad still faces glTF +z, which is Blender -y.
    check_near(flat.normals[v], glm::dvec3(0.0, -1.0, 0.0));
    // Computed tangents: u grows along glTF +x, mirrored to Blender -x; +v (after the flip)
    // along glTF +y, Blender +z. Seen from the front (-y) that layout is mirrored: w = -1.
    const glm::vec4 t = flat.tangents[v];
    check_near(glm::vec3(t), glm::dvec3(-1.0, 0.0, 0.0), 1e-4);
    CHECK(t.w == -1.0f);
    const glm::vec3 bitangent = t.w * glm::cross(flat.normals[v], glm::vec3(t));
    CHECK(bitangent.z > 0.9999f);
  }
  for (const glm::uvec3& triangle : mesh.triangles) {
    CHECK(glm::dot(face_normal(mesh, triangle), glm::dvec3(0.0, -1.0, 0.0)) > 0.999);
  }
}

TEST_CASE("glTF tangents from the file follow the axes and a mirror", "[geom]") {
  const bool mirrored = GENERATE(false, true);
  TempDir dir;
  GltfWriter writer(dir, "tangents", Container::EmbeddedDataUri);
  const int positions = writer.add_vec3({0, 0, 0, 1, 0, 0, 0, 1, 0});
  const int normals = writer.add_vec3({0, 0, 1, 0, 0, 1, 0, 0, 1});
  const int uvs = writer.add_vec2({0, 1, 1, 1, 0, 0});
  const int tangents =
      writer.add_data(std::vector<float>{1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1}, kFloat, "VEC4", 4);
  json& doc = writer.doc();
  doc["meshes"] = json::array({{{"primitives", json::array({{{"attributes",
                                                              {{"POSITION", positions},
                                                               {"NORMAL", normals},
                                                               {"TEXCOORD_0", uvs},
                                                               {"TANGENT", tangents}}}}})}}});
  json node = {{"mesh", 0}};
  if (mirrored) node["scale"] = {-1.0, 1.0, 1.0};
  doc["nodes"] = json::array({node});  // no scene: every root node is read
  const matgeom::TriangleMesh mesh = matgeom::read_gltf(writer.write()).mesh;

  REQUIRE(mesh.tangents.size() == 3);
  for (size_t v = 0; v < 3; ++v) {
    check_near(mesh.normals[v], glm::dvec3(0.0, -1.0, 0.0));
    check_near(glm::vec3(mesh.tangents[v]), glm::dvec3(mirrored ? -1.0 : 1.0, 0.0, 0.0));
    CHECK(mesh.tangents[v].w == (mirrored ? -1.0f : 1.0f));
  }
  // Winding is flipped by the mirror so that it keeps agreeing with the normals.
  CHECK(glm::dot(face_normal(mesh, mesh.triangles[0]), glm::dvec3(0.0, -1.0, 0.0)) > 0.999);
}

TEST_CASE("glTF triangle strips become consistently wound triangles", "[geom]") {
  TempDir dir;
  GltfWriter writer(dir, "strip", Container::Glb);
  const int positions = writer.add_vec3({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 2, 0});
  const int indices =
      writer.add_data(std::vector<uint32_t>{0, 1, 2, 3, 4}, kUnsignedInt, "SCALAR", 1);
  json& doc = writer.doc();
  doc["meshes"] =
      json::array({{{"primitives", json::array({{{"attributes", {{"POSITION", positions}}},
                                                 {"indices", indices},
                                                 {"mode", kModeTriangleStrip}}})}}});
  doc["nodes"] = json::array({{{"mesh", 0}}});
  doc["scenes"] = json::array({{{"nodes", {0}}}});
  const matgeom::TriangleMesh mesh = matgeom::read_gltf(writer.write()).mesh;
  REQUIRE(mesh.triangle_count() == 3);
  CHECK(mesh.uvs.empty());
  CHECK(mesh.tangents.empty());
  for (const glm::uvec3& triangle : mesh.triangles) {
    check_near(glm::vec3(face_normal(mesh, triangle)), glm::dvec3(0.0, -1.0, 0.0));
  }
}

// ---- Broken files: every one gives a runtime_error that names the file.

namespace {

// A one-triangle file with the given index list and positions.
std::string write_triangle(const TempDir& dir, const std::string& stem,
                           const std::vector<float>& positions,
                           const std::vector<uint16_t>& indices, int mode = 4) {
  GltfWriter writer(dir, stem, Container::EmbeddedDataUri);
  const int position_accessor = writer.add_vec3(positions);
  const int index_accessor = writer.add_data(indices, kUnsignedShort, "SCALAR", 1);
  writer.doc()["meshes"] =
      json::array({{{"primitives", json::array({{{"attributes", {{"POSITION", position_accessor}}},
                                                 {"indices", index_accessor},
                                                 {"mode", mode}}})}}});
  writer.doc()["nodes"] = json::array({{{"mesh", 0}}});
  return writer.write();
}

const std::vector<float> kTriangle = {0, 0, 0, 1, 0, 0, 0, 1, 0};

}  // namespace

TEST_CASE("glTF reader survives truncated and bit-flipped files", "[geom]") {
  const TempDir dir;
  for (const Container container : {Container::Glb, Container::EmbeddedDataUri}) {
    const std::string path = write_two_material_quad(dir, container);
    const std::string original = read_bytes(path);
    const std::string damaged_path = dir.file("damaged" + std::filesystem::path(path).extension().string());
    const auto read = [](const std::string& file) { return matgeom::read_gltf(file); };
    // Every truncation up to 2 KiB (headers, JSON, buffer starts), then every 37th length.
    for (size_t length = 0; length < original.size(); length += length < 2048 ? 1 : 37)
      check_reads_or_rejects(damaged_path, original.substr(0, length), read);
    std::mt19937 random(20261123u);
    for (int flip = 0; flip < 1000; ++flip) {
      std::string damaged = original;
      const size_t byte = random() % damaged.size();
      damaged[byte] = static_cast<char>(damaged[byte] ^ (1 << (random() % 8)));
      check_reads_or_rejects(damaged_path, damaged, read);
    }
  }
}

TEST_CASE("glTF reader errors name the file and the problem", "[geom]") {
  TempDir dir;
  using Catch::Matchers::Contains;

  SECTION("missing file") {
    const std::string path = dir.file("missing.gltf");
    CHECK_THAT(read_error(path), Contains(path) && Contains("no such file"));
  }
  SECTION("garbage bytes") {
    std::vector<uint8_t> garbage(300);
    for (size_t i = 0; i < garbage.size(); ++i) garbage[i] = static_cast<uint8_t>(i * 37 + 11);
    for (const char* name : {"garbage.gltf", "garbage.glb"}) {
      const std::string path = dir.file(name);
      write_bytes(path, garbage);
      CHECK_THAT(read_error(path), Contains(path));
    }
  }
  SECTION("truncated GLB") {
    GltfWriter writer(dir, "whole", Container::Glb);
    const int positions = writer.add_vec3(kTriangle);
    writer.doc()["meshes"] =
        json::array({{{"primitives", json::array({{{"attributes", {{"POSITION", positions}}}}})}}});
    writer.doc()["nodes"] = json::array({{{"mesh", 0}}});
    const std::string whole = writer.write();
    REQUIRE(matgeom::read_gltf(whole).mesh.triangle_count() == 1);

    std::ifstream in(whole, std::ios::binary);
    std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                               std::istreambuf_iterator<char>());
    bytes.resize(bytes.size() - 20);
    const std::string path = dir.file("truncated.glb");
    write_bytes(path, bytes);
    CHECK_THAT(read_error(path), Contains(path));
  }
  SECTION("index out of range") {
    const std::string path = write_triangle(dir, "bad_index", kTriangle, {0, 1, 7});
    CHECK_THAT(read_error(path), Contains(path) && Contains("out of range"));
  }
  SECTION("index count not a multiple of three") {
    const std::string path = write_triangle(dir, "bad_count", kTriangle, {0, 1, 2, 1});
    CHECK_THAT(read_error(path), Contains(path) && Contains("multiple of 3"));
  }
  SECTION("NaN vertex") {
    std::vector<float> positions = kTriangle;
    positions[4] = std::numeric_limits<float>::quiet_NaN();
    const std::string path = write_triangle(dir, "nan", positions, {0, 1, 2});
    CHECK_THAT(read_error(path), Contains(path) && Contains("non-finite vertex 1"));
  }
  SECTION("zero triangles") {
    const std::string degenerate = write_triangle(dir, "degenerate", kTriangle, {0, 0, 1});
    CHECK_THAT(read_error(degenerate), Contains(degenerate) && Contains("no triangles"));

    GltfWriter writer(dir, "empty", Container::EmbeddedDataUri);
    writer.doc()["nodes"] = json::array({{{"name", "no mesh"}}});
    const std::string empty = writer.write();
    CHECK_THAT(read_error(empty), Contains(empty) && Contains("no triangles"));
  }
  SECTION("unsupported primitive mode") {
    const std::string path = write_triangle(dir, "points", kTriangle, {0, 1, 2}, kModePoints);
    CHECK_THAT(read_error(path), Contains(path) && Contains("unsupported primitive mode"));
  }
  SECTION("accessor past the end of its buffer view") {
    GltfWriter writer(dir, "short_view", Container::EmbeddedDataUri);
    const int view = writer.add_view(kTriangle.data(), kTriangle.size() * sizeof(float));
    const int positions = writer.add_accessor(view, kFloat, 4, "VEC3");
    writer.doc()["meshes"] =
        json::array({{{"primitives", json::array({{{"attributes", {{"POSITION", positions}}}}})}}});
    writer.doc()["nodes"] = json::array({{{"mesh", 0}}});
    const std::string path = writer.write();
    CHECK_THAT(read_error(path), Contains(path) && Contains("run past the end"));
  }
  SECTION("texture transforms that cannot be read") {
    for (const auto& [transform, problem] :
         {std::pair{json{{"offset", {1.0, 2.0, 3.0}}}, "KHR_texture_transform offset needs 2 numbers"},
          std::pair{json{{"rotation", "quarter"}}, "KHR_texture_transform rotation is not a finite number"},
          std::pair{json{{"texCoord", -1}}, "texCoord -1 is negative"}}) {
      GltfWriter writer(dir, "placed", Container::Glb);
      const int positions = writer.add_vec3(kTriangle);
      writer.doc()["meshes"] = json::array(
          {{{"primitives", json::array({{{"attributes", {{"POSITION", positions}}}, {"material", 0}}})}}});
      writer.doc()["nodes"] = json::array({{{"mesh", 0}}});
      const int image = writer.add_image(encode_png(2, 2, 3, 8, kBaseColorPixels), "base.png");
      writer.doc()["textures"] = json::array({{{"source", image}}});
      writer.doc()["materials"] = json::array({{{"pbrMetallicRoughness",
                                                 {{"baseColorTexture",
                                                   {{"index", 0}, {"extensions", {{"KHR_texture_transform", transform}}}}}}}}});
      const std::string path = writer.write();
      CHECK_THAT(read_error(path), Contains(path) && Contains("baseColorTexture") && Contains(problem));
    }
  }
  SECTION("sheen that cannot be read") {
    for (const auto& [sheen, problem] :
         {std::pair{json{{"sheenColorFactor", {0.5, 0.5}}}, "sheenColorFactor needs 3 numbers"},
          std::pair{json{{"sheenColorFactor", {0.5, "red", 0.5}}}, "sheenColorFactor needs 3 numbers"},
          std::pair{json{{"sheenColorFactor", {0.5, 1.5, 0.5}}}, "sheenColorFactor 1.5 is outside [0, 1]"},
          std::pair{json{{"sheenRoughnessFactor", -0.25}}, "sheenRoughnessFactor -0.25 is outside [0, 1]"},
          std::pair{json{{"sheenRoughnessTexture", {{"index", 7}}}}, "texture 7 does not exist"}}) {
      GltfWriter writer(dir, "cloth", Container::Glb);
      const int positions = writer.add_vec3(kTriangle);
      writer.doc()["meshes"] = json::array(
          {{{"primitives", json::array({{{"attributes", {{"POSITION", positions}}}, {"material", 0}}})}}});
      writer.doc()["nodes"] = json::array({{{"mesh", 0}}});
      writer.doc()["materials"] = json::array({{{"extensions", {{"KHR_materials_sheen", sheen}}}}});
      const std::string path = writer.write();
      CHECK_THAT(read_error(path), Contains(path) && Contains("KHR_materials_sheen") && Contains(problem));
    }
  }
  SECTION("missing external image") {
    GltfWriter writer(dir, "lost_image", Container::ExternalFiles);
    const int positions = writer.add_vec3(kTriangle);
    writer.doc()["meshes"] = json::array(
        {{{"primitives",
           json::array({{{"attributes", {{"POSITION", positions}}}, {"material", 0}}})}}});
    writer.doc()["nodes"] = json::array({{{"mesh", 0}}});
    writer.doc()["images"] = json::array({{{"uri", "nowhere.png"}}});
    writer.doc()["textures"] = json::array({{{"source", 0}}});
    writer.doc()["materials"] =
        json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}});
    const std::string path = writer.write();
    CHECK_THAT(read_error(path), Contains(path));
  }
}

namespace {

// A triangle of material 0 (`material`), textured by `image` through a texture with sampler 0
// (`sampler`), when given.
std::string write_material_triangle(const TempDir& dir, const std::string& stem, const json& material,
                                    const std::vector<uint8_t>& image = {}, const json& sampler = json(),
                                    Container container = Container::Glb) {
  GltfWriter writer(dir, stem, container);
  const int positions = writer.add_vec3(kTriangle);
  writer.doc()["meshes"] =
      json::array({{{"primitives", json::array({{{"attributes", {{"POSITION", positions}}}, {"material", 0}}})}}});
  writer.doc()["nodes"] = json::array({{{"mesh", 0}}});
  json textured = material;
  if (!image.empty()) {
    json texture = {{"source", writer.add_image(image, stem + ".png")}};
    if (!sampler.is_null()) {
      writer.doc()["samplers"] = json::array({sampler});
      texture["sampler"] = 0;
    }
    writer.doc()["textures"] = json::array({texture});
    textured["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
  }
  writer.doc()["materials"] = json::array({textured});
  return writer.write();
}

// (encode_png checks its input with REQUIRE, so it runs inside a test.)
std::vector<uint8_t> grey_png() { return encode_png(2, 2, 1, {10, 20, 30, 40}); }

}  // namespace

TEST_CASE("glTF values tinygltf would pass unseen are checked as written", "[geom]") {
  TempDir dir;
  using Catch::Matchers::Contains;
  constexpr const char* kWrapModes = "33071 (CLAMP_TO_EDGE), 33648 (MIRRORED_REPEAT), 10497 (REPEAT)";

  SECTION("sampler values outside glTF's enums") {
    for (const auto& [sampler, problem] : {
             std::pair{json{{"wrapS", 1234}}, std::string("sampler 0 wrapS: 1234 is not one of glTF's values: ") + kWrapModes},
             std::pair{json{{"wrapT", "clamp"}}, std::string("sampler 0 wrapT: \"clamp\" is not one of glTF's values")},
             std::pair{json{{"wrapS", 33071.5}}, std::string("sampler 0 wrapS: 33071.5 is not one of")},
             std::pair{json{{"magFilter", 9984}}, std::string("sampler 0 magFilter: 9984 is not one of glTF's values: "
                                                              "9728 (NEAREST), 9729 (LINEAR)")},
             std::pair{json{{"minFilter", 5}}, std::string("sampler 0 minFilter: 5 is not one of glTF's values")},
         }) {
      const std::string path = write_material_triangle(dir, "sampled", json::object(), grey_png(), sampler);
      INFO(sampler.dump());
      CHECK_THAT(read_error(path), Contains(path + ": " + problem));
    }
    const std::string path = write_material_triangle(
        dir, "sampled", json::object(), grey_png(),
        {{"wrapS", kClampToEdge}, {"wrapT", 33648}, {"magFilter", 9728}, {"minFilter", 9987}});
    CHECK(matgeom::read_gltf(path).materials.at(0)[P::BaseColor].image == 0);
  }
  SECTION("alpha cutoffs and factors of the wrong type or sign") {
    for (const auto& [material, problem] : {
             std::pair{json{{"alphaMode", "MASK"}, {"alphaCutoff", -0.5}},
                       "material 0 alphaCutoff: -0.5 is negative (glTF's alphaCutoff is 0 or more)"},
             std::pair{json{{"alphaMode", "MASK"}, {"alphaCutoff", "half"}}, "material 0 alphaCutoff: \"half\" is not a number"},
             std::pair{json{{"pbrMetallicRoughness", {{"metallicFactor", "x"}}}},
                       "material 0 pbrMetallicRoughness.metallicFactor: \"x\" is not a number"},
             std::pair{json{{"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, "1", 1}}}}},
                       "material 0 pbrMetallicRoughness.baseColorFactor: [1,1,\"1\",1] is not an array of 4 numbers"},
             std::pair{json{{"emissiveFactor", {1, 1}}}, "material 0 emissiveFactor: [1,1] is not an array of 3 numbers"},
             std::pair{json{{"normalTexture", {{"index", 0}, {"scale", "big"}}}},
                       "material 0 normalTexture.scale: \"big\" is not a number"},
             std::pair{json{{"occlusionTexture", {{"index", -1}}}},
                       "material 0 occlusionTexture.index: -1 is not a whole number of 0 or more"},
             std::pair{json{{"alphaMode", 3}}, "material 0 alphaMode: 3 is not a string"},
         }) {
      const std::string path = write_material_triangle(dir, "factors", material);
      INFO(material.dump());
      CHECK_THAT(read_error(path), Contains(path + ": " + problem));
    }
    // JSON has no NaN, and a number beyond a double is no JSON number either.
    const std::string path = write_material_triangle(dir, "cutoff", {{"alphaMode", "MASK"}, {"alphaCutoff", 0.25}},
                                                     {}, json(), Container::EmbeddedDataUri);
    const std::string text = read_bytes(path);
    const size_t cutoff = text.find("0.25");
    REQUIRE(cutoff != std::string::npos);
    write_text(path, text.substr(0, cutoff) + "NaN" + text.substr(cutoff + 4));
    CHECK_THAT(read_error(path), Contains(path + ": not valid JSON (at byte "));
    write_text(path, text.substr(0, cutoff) + "1e999" + text.substr(cutoff + 4));
    CHECK_THAT(read_error(path), Contains(path + ": the JSON holds the number \"1e999\", beyond the range of a double"));
  }
  SECTION("images in formats not read, or damaged") {
    const std::vector<uint8_t> exr = {0x76, 0x2F, 0x31, 0x01, 2, 0, 0, 0, 'c', 'h', 'a', 'n', 'n', 'e', 'l', 's'};
    std::string path = write_material_triangle(dir, "exr", json::object(), exr);
    std::string error = read_error(path);
    CHECK_THAT(error, Contains(path + ": image 0: an OpenEXR image; images are read from PNG, JPEG, BMP or TGA files"));
    CHECK_THAT(error, !Contains("Unknown image format") && !Contains("STB"));
    std::vector<uint8_t> truncated = encode_png(4, 4, 3, std::vector<uint8_t>(48, 90));
    truncated.resize(truncated.size() - 30);
    path = write_material_triangle(dir, "truncated", json::object(), truncated);
    error = read_error(path);
    CHECK_THAT(error, Contains(path + ": image 0: the PNG data is damaged or cut short"));
    CHECK_THAT(error, !Contains("Unknown image format") && !Contains("STB"));
  }
}

TEST_CASE("glTF morph targets are refused unless every weight leaves the base shape", "[geom]") {
  TempDir dir;
  using Catch::Matchers::Contains;
  const auto write_morphed = [&](const json& mesh_weights, const json& node_weights) {
    GltfWriter writer(dir, "morphed", Container::Glb);
    const int positions = writer.add_vec3(kTriangle);
    const int offsets = writer.add_vec3({0, 0, 1, 0, 0, 1, 0, 0, 1});
    json mesh = {{"primitives", json::array({{{"attributes", {{"POSITION", positions}}},
                                              {"targets", json::array({{{"POSITION", offsets}}})}}})}};
    if (!mesh_weights.is_null()) mesh["weights"] = mesh_weights;
    json node = {{"mesh", 0}};
    if (!node_weights.is_null()) node["weights"] = node_weights;
    writer.doc()["meshes"] = json::array({mesh});
    writer.doc()["nodes"] = json::array({node});
    return writer.write();
  };
  std::string path = write_morphed({0.5}, json());
  CHECK_THAT(read_error(path), Contains(path + ": mesh 0 (node 0): morph target weights 0.5 are not applied; only "
                                               "the base shape is read, so every weight must be 0"));
  path = write_morphed({0.0}, {0.25});  // the node's weights replace the mesh's
  CHECK_THAT(read_error(path), Contains("morph target weights 0.25 are not applied"));
  // Weights of 0 (glTF's default) show the base shape: the triangle as written, z = 0.
  for (const auto& [mesh_weights, node_weights] : {std::pair{json(), json()}, std::pair{json{0.5}, json{0.0}}}) {
    const matgeom::ObjectAsset asset = matgeom::read_gltf(write_morphed(mesh_weights, node_weights));
    REQUIRE(asset.mesh.vertex_count() == 3);
    for (const glm::vec3& p : asset.mesh.positions) CHECK(p.y == 0.0f);  // glTF's z is Blender's -y
  }
}

TEST_CASE("glTF errors never echo a data URI", "[geom]") {
  TempDir dir;
  using Catch::Matchers::Contains;
  // 30,000 vertices of float positions: a buffer of 360,000 bytes, 480,000 characters of base64.
  std::vector<float> positions(90000, 0.5f);
  GltfWriter writer(dir, "long", Container::EmbeddedDataUri);
  writer.add_vec3(positions);
  writer.doc()["meshes"] = json::array({{{"primitives", json::array({{{"attributes", {{"POSITION", 0}}}}})}}});
  writer.doc()["nodes"] = json::array({{{"mesh", 0}}});
  const std::string path = writer.write();
  json doc = json::parse(read_bytes(path));
  doc["buffers"][0]["byteLength"] = 360004;
  write_text(path, doc.dump());
  std::string error = read_error(path);
  CHECK_THAT(error, Contains(path + ": buffer 0: byteLength 360004, but its data URI "
                                    "(\"data:application/octet-stream;base64,\" and 480000 characters) decodes to "
                                    "360000 bytes"));
  CHECK(error.size() < path.size() + 200);
  // tinygltf takes a data URI of a media type it does not decode for a file name, and quoted it.
  doc["buffers"][0]["byteLength"] = 360000;
  doc["buffers"][0]["uri"] = "data:application/x-unknown;base64," + std::string(480000, 'A');
  write_text(path, doc.dump());
  error = read_error(path);
  CHECK_THAT(error, Contains(path + ": buffer 0 uri: a data URI starting \"data:application/x-unknown;base64,\"; "
                                    "the data URIs read are base64 of application/octet-stream, "
                                    "application/gltf-buffer"));
  CHECK(error.size() < path.size() + 200);
  // Data that decodes to nothing (no base64 character) fails in tinygltf, which quotes the URI:
  // passed on cut after its media type.
  doc["buffers"][0]["byteLength"] = 0;
  doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + std::string(480000, '!');
  write_text(path, doc.dump());
  error = read_error(path);
  CHECK_THAT(error, Contains(path + ": ") && Contains("data:application/octet-stream;base64,<480000 characters of data>"));
  CHECK(error.size() < path.size() + 700);
}

TEST_CASE("glTF reader walks a node hierarchy 100,000 levels deep without recursion", "[geom]") {
  TempDir dir;
  GltfWriter writer(dir, "deep", Container::EmbeddedDataUri);
  const int positions = writer.add_vec3(kTriangle);
  writer.doc()["meshes"] =
      json::array({{{"primitives", json::array({{{"attributes", {{"POSITION", positions}}}}})}}});
  // A chain of nodes, each 1/1024 m along glTF's +X from its parent (exact in binary), the
  // triangle at the end.
  constexpr int kLevels = 100000;
  json nodes = json::array();
  for (int level = 0; level < kLevels; ++level) {
    json node = {{"translation", {1.0 / 1024.0, 0.0, 0.0}}};
    if (level + 1 < kLevels) node["children"] = json::array({level + 1});
    else node["mesh"] = 0;
    nodes.push_back(node);
  }
  writer.doc()["nodes"] = nodes;
  writer.doc()["scenes"] = json::array({{{"nodes", json::array({0})}}});
  writer.doc()["scene"] = 0;
  const matgeom::ObjectAsset asset = matgeom::read_gltf(writer.write());
  REQUIRE(asset.mesh.triangle_count() == 1);
  CHECK(asset.mesh.positions[0].x == Approx(kLevels / 1024.0));
}

TEST_CASE("glTF textures are read on the UV set they name", "[geom]") {
  TempDir dir;
  // One triangle with two UV sets: TEXCOORD_0 all (0, 0), TEXCOORD_1 the corners of the unit square.
  const auto write = [&](const json& material, bool with_second_set) {
    GltfWriter writer(dir, "two_sets", Container::Glb);
    json attributes = {{"POSITION", writer.add_vec3(kTriangle)}, {"TEXCOORD_0", writer.add_vec2({0, 0, 0, 0, 0, 0})}};
    if (with_second_set) attributes["TEXCOORD_1"] = writer.add_vec2({0, 0, 1, 0, 0, 1});
    writer.doc()["meshes"] = json::array({{{"primitives", json::array({{{"attributes", attributes}, {"material", 0}}})}}});
    writer.doc()["nodes"] = json::array({{{"mesh", 0}}});
    const int image = writer.add_image(encode_png(2, 2, 3, 8, kBaseColorPixels), "base.png");
    writer.doc()["textures"] = json::array({{{"source", image}}});
    writer.doc()["materials"] = json::array({material});
    return writer.write();
  };
  SECTION("texCoord 1 reads TEXCOORD_1 (v flipped as TEXCOORD_0 is)") {
    const matgeom::ObjectAsset asset =
        matgeom::read_gltf(write({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}, {"texCoord", 1}}}}}}, true));
    REQUIRE(asset.mesh.uvs.size() == 3);
    CHECK(asset.mesh.uvs[1] == glm::vec2(1.0f, 1.0f));
    CHECK(asset.mesh.uvs[2] == glm::vec2(0.0f, 0.0f));
    CHECK(asset.notes.empty());
  }
  SECTION("KHR_texture_transform's texCoord replaces the textureInfo's") {
    const json info = {{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"texCoord", 1}}}}}};
    const matgeom::ObjectAsset asset = matgeom::read_gltf(write({{"pbrMetallicRoughness", {{"baseColorTexture", info}}}}, true));
    CHECK(asset.mesh.uvs[1] == glm::vec2(1.0f, 1.0f));
  }
  SECTION("two sets in one material are refused, naming both textures") {
    const json material = {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}, {"texCoord", 1}}}}},
                           {"normalTexture", {{"index", 0}}}};
    const std::string path = write(material, true);
    CHECK_THAT(read_error(path), Catch::Matchers::Contains(
                                     path + ": material 0 normalTexture samples TEXCOORD_0, but material 0 baseColorTexture samples "
                                            "TEXCOORD_1: a material's textures are read on one UV set"));
  }
  SECTION("a set the primitive lacks is said in the notes") {
    const matgeom::ObjectAsset asset =
        matgeom::read_gltf(write({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}, {"texCoord", 1}}}}}}, false));
    REQUIRE(asset.notes.size() == 1);
    CHECK_THAT(asset.notes[0], Catch::Matchers::Contains("mesh 0 primitive 0 has no TEXCOORD_1"));
  }
}

namespace {

// A triangle with TEXCOORD_0, in material 0, as the file's one node.
void add_uv_triangle_of_material_0(GltfWriter& writer) {
  writer.doc()["meshes"] =
      json::array({{{"primitives", json::array({{{"attributes", {{"POSITION", writer.add_vec3(kTriangle)},
                                                                  {"TEXCOORD_0", writer.add_vec2({0, 0, 1, 0, 0, 1})}}},
                                                 {"material", 0}}})}}});
  writer.doc()["nodes"] = json::array({{{"mesh", 0}}});
}

}  // namespace

TEST_CASE("glTF specular-glossiness becomes the nearest metallic-roughness material, and says so", "[geom]") {
  TempDir dir;
  GltfWriter writer(dir, "spec_gloss", Container::Glb);
  add_uv_triangle_of_material_0(writer);
  // A 2 x 1 RGBA specular-glossiness map: alpha (glossiness) 255 and 51.
  const int image = writer.add_image(encode_png(2, 1, 4, 8, {10, 10, 10, 255, 10, 10, 10, 51}), "sg.png");
  writer.doc()["textures"] = json::array({{{"source", image}}});
  writer.doc()["extensionsUsed"] = json::array({"KHR_materials_pbrSpecularGlossiness", "KHR_materials_volume"});
  writer.doc()["materials"] = json::array({{{"extensions",
                                             {{"KHR_materials_pbrSpecularGlossiness",
                                               {{"diffuseFactor", {0.5, 0.25, 0.125, 1.0}},
                                                {"specularFactor", {0.04, 0.04, 0.04}},
                                                {"glossinessFactor", 0.8},
                                                {"specularGlossinessTexture", {{"index", 0}}}}}}}}});
  const matgeom::ObjectAsset asset = matgeom::read_gltf(writer.write());
  const matmaterial::MaterialInputs& m = asset.materials.at(0);
  CHECK(m.color(P::BaseColor) == glm::dvec3(0.5, 0.25, 0.125));
  CHECK(m.scalar(P::Metallic) == 0.0);
  CHECK(m.scalar(P::Specular) == Approx(0.5));  // 0.04 / 0.08
  // Roughness = 1 - 0.8 x A: a baked one-channel map of 255 - 0.8 x 255 = 51 and 255 - 0.8 x 51 = 214.
  REQUIRE(m[P::Roughness].image >= 0);
  CHECK(m.scalar(P::Roughness) == 1.0);
  const matbase::ImagePixels& roughness = asset.images.at(static_cast<size_t>(m[P::Roughness].image));
  CHECK(roughness.channels == 1);
  CHECK(roughness.data == std::vector<uint8_t>{51, 214});
  const auto said = [&](const std::string& words) {
    return std::any_of(asset.notes.begin(), asset.notes.end(), [&](const std::string& note) { return note.find(words) != std::string::npos; });
  };
  CHECK(said("KHR_materials_pbrSpecularGlossiness: converted to the nearest metallic-roughness material"));
  CHECK(said("the glTF extension \"KHR_materials_volume\" is not applied"));
  CHECK(!said("KHR_materials_pbrSpecularGlossiness\" is not applied"));
}

TEST_CASE("glTF clearcoatNormalTexture is said not to be applied", "[geom]") {
  TempDir dir;
  GltfWriter writer(dir, "coat", Container::Glb);
  add_uv_triangle_of_material_0(writer);
  const int image = writer.add_image(encode_png(2, 2, 3, 8, kBaseColorPixels), "n.png");
  writer.doc()["textures"] = json::array({{{"source", image}}});
  writer.doc()["materials"] = json::array(
      {{{"extensions", {{"KHR_materials_clearcoat", {{"clearcoatFactor", 1.0}, {"clearcoatNormalTexture", {{"index", 0}}}}}}}}});
  const matgeom::ObjectAsset asset = matgeom::read_gltf(writer.write());
  CHECK(asset.materials.at(0).scalar(P::Clearcoat) == 1.0);
  REQUIRE(asset.notes.size() == 1);
  CHECK(asset.notes[0] == "material 0 KHR_materials_clearcoat clearcoatNormalTexture is not applied (the coat keeps the surface's normal)");
}

TEST_CASE("glTF vertex colours (COLOR_0) are said not to be applied", "[geom]") {
  TempDir dir;
  GltfWriter writer(dir, "coloured", Container::Glb);
  add_uv_triangle_of_material_0(writer);
  writer.doc()["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = writer.add_vec3({1, 0, 0, 0, 1, 0, 0, 0, 1});
  writer.doc()["materials"] = json::array({json::object()});
  const matgeom::ObjectAsset asset = matgeom::read_gltf(writer.write());
  CHECK(asset.mesh.colors.empty());
  CHECK(!asset.materials.at(0).vertex_colors);
  REQUIRE(asset.notes.size() == 1);
  CHECK(asset.notes[0] == "the vertex colours (COLOR_0) are not applied: the materials' base colours stand alone");
}
