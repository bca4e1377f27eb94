// The corpus of tests/geom/data/mesh_corpus: files shaped as other tools write them, each read by
// read_object and held to what expected.json says of it (a mesh with given traits, or a refusal
// whose message holds given words).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "matgeom/io/mesh_io.h"
#include "matbase/text_encoding.h"
#include "matgeom/mesh.h"
#include "support/temp_dir.h"
#include "support/test_files.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kCorpus = MATPREDICT_MESH_CORPUS;

// A little-endian 32-bit number's bytes.
std::string le32(uint32_t value) {
  std::string bytes;
  for (int k = 0; k < 4; ++k) bytes.push_back(static_cast<char>((value >> (8 * k)) & 0xFF));
  return bytes;
}

// The bytes a "made" recipe of expected.json gives, from the corpus's text files.
std::string made_bytes(const json& recipe) {
  const auto text_of = [](const json& file) {
    const std::string text = read_bytes((kCorpus / file.get<std::string>()).string());
    REQUIRE(std::all_of(text.begin(), text.end(), [](char c) { return static_cast<unsigned char>(c) < 0x80; }));
    return text;
  };
  if (recipe.contains("utf16_of")) {
    std::string utf16 = "\xFF\xFE";  // little-endian, as Windows writes it
    for (const char c : text_of(recipe["utf16_of"])) utf16 += std::string{c, '\0'};
    return utf16;
  }
  if (recipe.contains("utf8_bom_of")) return "\xEF\xBB\xBF" + text_of(recipe["utf8_bom_of"]);
  if (recipe.contains("glb_version_1_of")) {
    // KHR_binary_glTF: magic, version 1, total length, content length, content format 0 (JSON).
    const std::string content = text_of(recipe["glb_version_1_of"]);
    const auto length = static_cast<uint32_t>(content.size());
    return "glTF" + le32(1) + le32(20 + length) + le32(length) + le32(0) + content;
  }
  const std::vector<uint8_t> rgb = recipe.at("png_rgb").get<std::vector<uint8_t>>();
  std::vector<uint8_t> pixels;
  for (int texel = 0; texel < 16; ++texel) pixels.insert(pixels.end(), rgb.begin(), rgb.end());
  const std::vector<uint8_t> png = encode_png(4, 4, 3, pixels);
  return std::string(png.begin(), png.end());
}

// The corpus in `folder`: its files copied, and those of the "made" recipes written.
void make_corpus(const json& manifest, const fs::path& folder) {
  fs::copy(kCorpus, folder, fs::copy_options::recursive);
  for (const json& recipe : manifest.at("made")) {
    const fs::path file = folder / recipe.at("file").get<std::string>();
    fs::create_directories(file.parent_path());
    write_bytes(file.string(), made_bytes(recipe));
  }
}

glm::vec3 face_normal(const matgeom::TriangleMesh& mesh, size_t t) {
  const glm::uvec3& tri = mesh.triangles[t];
  return glm::normalize(glm::cross(mesh.positions[tri[1]] - mesh.positions[tri[0]], mesh.positions[tri[2]] - mesh.positions[tri[0]]));
}

// Flat: no normals (flat shading), or every corner's normal is its face's.
bool is_flat(const matgeom::TriangleMesh& mesh) {
  if (mesh.normals.empty()) return true;
  for (size_t t = 0; t < mesh.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k)
      if (glm::length(mesh.normals[mesh.triangles[t][k]] - face_normal(mesh, t)) > 1e-5f) return false;
  return true;
}

// Smooth: the corners at one position share one normal, which no face of a cube has.
bool is_smooth(const matgeom::TriangleMesh& mesh) {
  if (mesh.normals.empty()) return false;
  struct Less {
    bool operator()(const glm::vec3& a, const glm::vec3& b) const {
      return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
    }
  };
  std::map<glm::vec3, glm::vec3, Less> normal_at;
  for (const glm::uvec3& tri : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const auto [found, inserted] = normal_at.emplace(mesh.positions[tri[k]], mesh.normals[tri[k]]);
      if (!inserted && glm::length(found->second - mesh.normals[tri[k]]) > 1e-5f) return false;
    }
  return true;
}

void check_reads(const fs::path& path, const json& expected) {
  const matgeom::ObjectAsset asset = matgeom::read_object(path.string());
  const matgeom::TriangleMesh& mesh = asset.mesh;
  if (expected.contains("triangles")) CHECK(mesh.triangle_count() == expected["triangles"].get<size_t>());
  if (expected.contains("shading")) {
    const std::string shading = expected["shading"];
    if (shading == "flat") CHECK(is_flat(mesh));
    if (shading == "smooth") CHECK(is_smooth(mesh));
  }
  if (expected.contains("parts")) CHECK(mesh.part_names == expected["parts"].get<std::vector<std::string>>());
  const auto part = [&](const std::string& name) {
    for (size_t k = 0; k < mesh.part_names.size(); ++k)
      if (mesh.part_names[k] == name) return k;
    FAIL("no part " << name);
    return size_t{0};
  };
  using P = matmaterial::MaterialParameter;
  const json textured = expected.value("base_color_textured", json::array());
  const json colours = expected.value("base_color", json::object());
  for (const json& name : textured) {
    const matmaterial::MaterialInputs& material = asset.materials.at(part(name.get<std::string>()));
    CHECK(material[P::BaseColor].image >= 0);
  }
  for (const json& words : expected.value("notes", json::array())) {
    INFO("notes must say: " << words.get<std::string>());
    CHECK(std::any_of(asset.notes.begin(), asset.notes.end(),
                      [&](const std::string& note) { return note.find(words.get<std::string>()) != std::string::npos; }));
  }
  for (const auto& [name, colour] : colours.items()) {
    const glm::dvec3 actual = asset.materials.at(part(name)).color(P::BaseColor);
    for (int c = 0; c < 3; ++c) CHECK(actual[c] == Approx(colour[static_cast<size_t>(c)].get<double>()).margin(1e-6));
  }
}

void check_refused(const fs::path& path, const json& words) {
  std::string message;
  try {
    matgeom::read_object(path.string());
  } catch (const std::runtime_error& error) {
    message = error.what();
  }
  INFO("message: " << message);
  REQUIRE(!message.empty());
  // Whatever bytes the file holds, the message is valid UTF-8.
  CHECK(matbase::valid_utf8(message) == message);
  CHECK(message.rfind(path.string() + ": ", 0) == 0);
  for (const json& word : words) CHECK(message.find(word.get<std::string>()) != std::string::npos);
}

}  // namespace

TEST_CASE("every file of the mesh corpus reads, or is refused, as expected.json says", "[geom]") {
  std::ifstream in(kCorpus / "expected.json");
  REQUIRE(in.good());
  const json manifest = json::parse(in);
  const json& files = manifest.at("files");
  REQUIRE(!files.empty());
  TempDir made;
  const fs::path corpus = made.path() / "mesh_corpus";
  make_corpus(manifest, corpus);
  for (const json& entry : files) {
    const fs::path path = corpus / entry.at("file").get<std::string>();
    SECTION(entry.at("file").get<std::string>()) {
      REQUIRE(fs::is_regular_file(path));
      if (entry.contains("reads")) check_reads(path, entry["reads"]);
      else check_refused(path, entry.at("refused"));
    }
  }
}

TEST_CASE("auto_smooth_deg smooths the faces a file gives no normals, up to its angle", "[geom]") {
  for (const char* file : {"obj/cube_flat_no_normals.obj", "ply/cube_no_normals.ply", "gltf/cube_no_normals.gltf"}) {
    INFO(file);
    const std::string path = (kCorpus / file).string();
    // A cube's faces meet at 90 degrees: sharp at 30, smooth at 100 (Blender's Auto Smooth).
    CHECK(is_flat(matgeom::read_object(path, {30.0}).mesh));
    CHECK(is_smooth(matgeom::read_object(path, {100.0}).mesh));
  }
}
