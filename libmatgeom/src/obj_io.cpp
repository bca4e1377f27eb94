#include "matgeom/obj_io.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <utility>
#include <vector>

#include <tiny_gltf.h>
#include <tiny_obj_loader.h>

#include "file_error.h"
#include "image_bytes.h"
#include "matgeom/atomic_file.h"
#include "matgeom/text.h"
#include "matgeom/tangents.h"

// Reading is four steps: the OBJ text is screened for the inputs tinyobjloader 2.0.0rc10 handles
// badly; tinyobjloader parses and triangulates it, reading every "mtllib" through
// MaterialLibraries, which marks what each material leaves out; the faces become one vertex per
// distinct v/vt/vn triple with a part per material slot or group; the used MTL materials become
// MaterialDescs as Blender's OBJ importer builds its Principled BSDF. Writing is done by hand.
//
// Axes: OBJ files are +Y up. As in Blender's importer with its default axes (forward -Z, up Y),
// (x, y, z) in the file is (x, -z, y) in Blender's +Z up frame; write_obj converts back.
// UVs need no conversion: OBJ's v points up the image, as Blender's does.

namespace matgeom {
namespace {

namespace fs = std::filesystem;

// The whole file, or false when it is not a readable regular file.
bool read_whole_file(const fs::path& file, std::string& bytes) {
  std::error_code error;
  if (!fs::is_regular_file(file, error)) return false;
  std::ifstream in(file, std::ios::binary);
  if (!in) return false;
  bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return !in.bad();
}

// ---------------------------------------------------------------------------------------------
// Text as tinyobjloader sees it

// Calls visit(begin, end) for every line of `text`, split where tinyobjloader's safeGetline
// splits: at \n, \r\n or \r.
template <typename Visit>
void for_each_line(const std::string& text, Visit visit) {
  size_t begin = 0;
  while (begin < text.size()) {
    size_t end = text.find_first_of("\r\n", begin);
    if (end == std::string::npos) end = text.size();
    visit(begin, end);
    const bool crlf = end + 1 < text.size() && text[end] == '\r' && text[end + 1] == '\n';
    begin = end + (crlf ? 2 : 1);
  }
}

// The keyword a line starts with as tinyobjloader tests keywords: after leading blanks and up to
// the next blank; empty when no blank follows it (tinyobjloader then ignores the line).
std::string_view line_keyword(std::string_view line) {
  const size_t begin = line.find_first_not_of(" \t");
  if (begin == std::string_view::npos) return {};
  const size_t end = line.find_first_of(" \t", begin);
  if (end == std::string_view::npos) return {};
  return line.substr(begin, end - begin);
}

// Blank-separated words after a line's keyword, up to the end of the line or a NUL byte (where
// tinyobjloader's C-string parsing stops).
size_t count_arguments(std::string_view line) {
  line = line.substr(0, line.find('\0'));
  size_t position = line.find_first_not_of(" \t");
  position = line.find_first_of(" \t", position);
  size_t count = 0;
  while (true) {
    position = line.find_first_not_of(" \t", position);
    if (position == std::string_view::npos) return count;
    ++count;
    position = line.find_first_of(" \t", position);
  }
}

// tinyobjloader's ear clipping takes time quadratic in a polygon's corners (about 0.2 s for
// 8000 on a star-shaped polygon), so a hostile file could stall the reader for minutes with one
// face; real polygons stay far below this.
constexpr size_t kMaxPolygonCorners = 10000;

// Prepares OBJ text for tinyobjloader 2.0.0rc10, which mishandles two statements that mean
// nothing to a triangle mesh: it copies every "t" (subdivision tag) line, with up to 3 x 8192
// values each, into every shape, so a few kilobytes of tags can claim gigabytes; and it converts
// "vw" (skin weight) joint numbers to int unchecked, undefined for 1e40. Their lines are blanked,
// which keeps the line numbers of tinyobjloader's messages. Polygons with too many corners are
// refused.
void screen_obj_text(const std::string& path, std::string& text) {
  for_each_line(text, [&](size_t begin, size_t end) {
    const std::string_view line(text.data() + begin, end - begin);
    const std::string_view keyword = line_keyword(line);
    if (keyword == "t" || keyword == "vw") {
      std::fill(text.begin() + static_cast<std::ptrdiff_t>(begin),
                text.begin() + static_cast<std::ptrdiff_t>(end), ' ');
      return;
    }
    const size_t corners = keyword == "f" ? count_arguments(line) : 0;
    if (corners > kMaxPolygonCorners) {
      fail(path, concat("a face has ", corners, " corners; more than ", kMaxPolygonCorners,
                        " are refused"));
    }
  });
}

// tinyobjloader fills whatever a material leaves out with its own defaults (Ns 1, Ka 0, Pr 0...),
// indistinguishable from written values. Blender's MTL parser (io/wavefront_obj/importer/
// obj_import_file_reader.cc) marks them -1 instead, and its importer then picks defaults that
// depend on illum. Starting every material with these lines makes tinyobjloader report the same
// markers (a value the file gives comes later and replaces its marker).
constexpr const char* kNotGivenMarkers =
    "Ns -1\nKa -1 -1 -1\nKd -1 -1 -1\nKs -1 -1 -1\nPr -1\nPm -1\n";

// An .mtl text with kNotGivenMarkers at the start and after every "newmtl" line, recognised as
// tinyobjloader's LoadMtl recognises it (trailing blanks trimmed, then "newmtl" and a blank).
// Lines end in \n after this.
std::string with_not_given_markers(const std::string& text) {
  std::string marked = kNotGivenMarkers;
  for_each_line(text, [&](size_t begin, size_t end) {
    const std::string_view line(text.data() + begin, end - begin);
    const size_t last = line.find_last_not_of(" \t");
    const std::string_view trimmed = line.substr(0, last == std::string_view::npos ? 0 : last + 1);
    if (line_keyword(trimmed) != "newmtl") {
      marked.append(line.data(), line.size()).push_back('\n');
      return;
    }
    // Blender trims material names. tinyobjloader keeps the blanks after the first, and then
    // "usemtl", which reads one word, would miss the material.
    const size_t name = trimmed.find_first_not_of(" \t", trimmed.find("newmtl") + 6);
    marked.append("newmtl ").append(trimmed.substr(name)).append("\n").append(kNotGivenMarkers);
  });
  return marked;
}

// ---------------------------------------------------------------------------------------------
// Loading

// Reads the .mtl files "mtllib" names for tinyobjloader, relative to the OBJ's directory as
// Blender resolves them, remembering the file each material comes from and the files that
// could not be read (tinyobjloader would only warn about those).
class MaterialLibraries : public tinyobj::MaterialReader {
 public:
  explicit MaterialLibraries(fs::path obj_directory) : obj_directory_(std::move(obj_directory)) {}

  bool operator()(const std::string& library, std::vector<tinyobj::material_t>* materials,
                  std::map<std::string, int>* material_map, std::string* warnings,
                  std::string* errors) override {
    const fs::path file = obj_directory_ / library;
    std::string text;
    if (!read_whole_file(file, text)) {
      missing_.push_back(file.string());
      return false;
    }
    std::istringstream stream(with_not_given_markers(text));
    tinyobj::LoadMtl(material_map, materials, &stream, warnings, errors);
    sources_.resize(materials->size(), file.string());
    return true;
  }

  const std::vector<std::string>& sources() const { return sources_; }
  const std::vector<std::string>& missing() const { return missing_; }

 private:
  fs::path obj_directory_;
  std::vector<std::string> sources_;  // the .mtl file of material k
  std::vector<std::string> missing_;
};

struct ObjFile {
  std::string path;
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::vector<std::string> material_libraries;  // the .mtl file of material k
  std::string warnings;
};

ObjFile load_obj(const std::string& path) {
  std::string text;
  if (!read_whole_file(path, text)) fail(path, "no such file");
  screen_obj_text(path, text);

  ObjFile file;
  file.path = path;
  std::istringstream stream(text);
  MaterialLibraries libraries(fs::path(path).parent_path());
  std::string errors;
  const bool parsed = tinyobj::LoadObj(&file.attrib, &file.shapes, &file.materials, &file.warnings,
                                       &errors, &stream, &libraries, /*triangulate=*/true,
                                       /*default_vcols_fallback=*/false);
  if (!libraries.missing().empty()) {
    fail(path, "cannot open material library " + libraries.missing().front());
  }
  if (!parsed || !errors.empty()) fail(path, "tinyobjloader: " + trim(errors));
  file.material_libraries = libraries.sources();
  return file;
}

// ---------------------------------------------------------------------------------------------
// Checks on what tinyobjloader returns

void check_finite(const std::string& path, const std::vector<tinyobj::real_t>& values,
                  size_t components, const char* what) {
  for (size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) fail(path, concat("non-finite ", what, " ", i / components + 1));
  }
}

// tinyobjloader resolves relative indices but does not range-check them; -1 means "none" for
// texture coordinates and normals. (A relative index resolving to exactly -1 is therefore
// indistinguishable from none.)
void check_index(const std::string& path, int index, size_t count, bool optional,
                 const char* what) {
  if (optional && index == -1) return;
  if (index >= 0 && static_cast<size_t>(index) < count) return;
  fail(path, concat("face index out of range: ", what, " ", static_cast<long long>(index) + 1,
                    " but the file has ", count));
}

// tinyobjloader drops a quad with an index past the end instead of passing it on, and warns;
// these phrases are its warnings about indices beyond the arrays.
void check_index_warnings(const ObjFile& file) {
  for (const char* phrase : {"indices out of bounds", "invalid vertex index"}) {
    const size_t found = file.warnings.find(phrase);
    if (found == std::string::npos) continue;
    const size_t line_begin = file.warnings.rfind('\n', found);
    const size_t begin = line_begin == std::string::npos ? 0 : line_begin + 1;
    const std::string line = file.warnings.substr(begin, file.warnings.find('\n', found) - begin);
    fail(file.path, "face index out of range (tinyobjloader: " + trim(line) + ")");
  }
}

void check_indices(const ObjFile& file) {
  const tinyobj::attrib_t& attrib = file.attrib;
  for (const tinyobj::shape_t& shape : file.shapes) {
    // Triangulation leaves three corners per face.
    if (shape.mesh.indices.size() != 3 * shape.mesh.material_ids.size()) {
      fail(file.path, "tinyobjloader returned faces that are not triangles");
    }
    for (const tinyobj::index_t& corner : shape.mesh.indices) {
      check_index(file.path, corner.vertex_index, attrib.vertices.size() / 3, false, "position");
      check_index(file.path, corner.texcoord_index, attrib.texcoords.size() / 2, true,
                  "texture coordinate");
      check_index(file.path, corner.normal_index, attrib.normals.size() / 3, true, "normal");
    }
  }
  check_index_warnings(file);
}

// ---------------------------------------------------------------------------------------------
// Parts

// Which part each face of each shape is in, and each part's name and material (an index into
// the file's materials, -1 for none).
struct PartTable {
  std::vector<std::string> names;
  std::vector<int> materials;
  std::vector<std::vector<uint32_t>> face_parts;  // [shape][face]
};

// Parts from material slots: the materials faces use, in the order the .mtl files define them,
// then "default" for faces without one ("usemtl" naming no defined material counts as none).
PartTable parts_by_material(const ObjFile& file) {
  std::set<int> used;
  for (const tinyobj::shape_t& shape : file.shapes) {
    used.insert(shape.mesh.material_ids.begin(), shape.mesh.material_ids.end());
  }
  PartTable table;
  std::map<int, uint32_t> part_of_material;
  for (const int material : used) {
    if (material < 0) continue;
    part_of_material[material] = static_cast<uint32_t>(table.names.size());
    table.names.push_back(file.materials[static_cast<size_t>(material)].name);
    table.materials.push_back(material);
  }
  if (used.count(-1) != 0) {
    part_of_material[-1] = static_cast<uint32_t>(table.names.size());
    table.names.push_back("default");
    table.materials.push_back(-1);
  }
  for (const tinyobj::shape_t& shape : file.shapes) {
    std::vector<uint32_t>& parts = table.face_parts.emplace_back();
    for (const int material : shape.mesh.material_ids) parts.push_back(part_of_material[material]);
  }
  return table;
}

// Parts from groups: one per distinct "g"/"o" name in file order, unnamed faces in "default";
// a part's material is that of its first face.
PartTable parts_by_group(const ObjFile& file) {
  PartTable table;
  std::map<std::string, uint32_t> part_of_name;
  for (const tinyobj::shape_t& shape : file.shapes) {
    std::vector<uint32_t>& parts = table.face_parts.emplace_back();
    if (shape.mesh.material_ids.empty()) continue;
    // Blender trims names; tinyobjloader keeps what follows "o " up to the end of the line.
    const std::string trimmed = trim(shape.name);
    const std::string name = trimmed.empty() ? "default" : trimmed;
    const auto [found, inserted] =
        part_of_name.emplace(name, static_cast<uint32_t>(table.names.size()));
    if (inserted) {
      table.names.push_back(name);
      table.materials.push_back(shape.mesh.material_ids.front());
    }
    parts.assign(shape.mesh.material_ids.size(), found->second);
  }
  return table;
}

// ---------------------------------------------------------------------------------------------
// Geometry

glm::vec3 obj_to_blender(const std::vector<tinyobj::real_t>& xyz, int index) {
  const size_t i = 3 * static_cast<size_t>(index);
  return {xyz[i], -xyz[i + 2], xyz[i + 1]};
}

// The mesh with a record of where its vertices came from.
struct AssembledMesh {
  TriangleMesh mesh;
  std::vector<int> file_positions;  // the file's position index of each vertex
  std::vector<bool> normal_missing;
};

class MeshAssembler {
 public:
  explicit MeshAssembler(const ObjFile& file) : attrib_(file.attrib) {
    for (const tinyobj::shape_t& shape : file.shapes) {
      for (const tinyobj::index_t& corner : shape.mesh.indices) {
        with_uvs_ = with_uvs_ || corner.texcoord_index >= 0;
      }
    }
  }

  // Triangles that repeat a position have no surface and are dropped (as read_gltf drops
  // triangles that repeat a vertex).
  void add_triangle(const tinyobj::index_t* corners, uint32_t part) {
    const int a = corners[0].vertex_index, b = corners[1].vertex_index, c = corners[2].vertex_index;
    if (a == b || b == c || c == a) return;
    // One statement each: vertices are numbered in corner order.
    const uint32_t first = vertex(corners[0]);
    const uint32_t second = vertex(corners[1]);
    const uint32_t third = vertex(corners[2]);
    assembled_.mesh.triangles.emplace_back(first, second, third);
    assembled_.mesh.triangle_parts.push_back(part);
  }

  AssembledMesh take() { return std::move(assembled_); }

 private:
  // One vertex per distinct (v, vt, vn) triple, numbered in order of first use.
  uint32_t vertex(const tinyobj::index_t& corner) {
    const std::array<int, 3> key = {corner.vertex_index, corner.texcoord_index,
                                    corner.normal_index};
    const auto [found, inserted] =
        vertex_of_corner_.emplace(key, static_cast<uint32_t>(assembled_.mesh.positions.size()));
    if (inserted) add_vertex(corner);
    return found->second;
  }

  void add_vertex(const tinyobj::index_t& corner) {
    TriangleMesh& mesh = assembled_.mesh;
    mesh.positions.push_back(obj_to_blender(attrib_.vertices, corner.vertex_index));
    assembled_.file_positions.push_back(corner.vertex_index);
    // Corners without a texture coordinate in a file that has them get (0, 0).
    if (with_uvs_) {
      const size_t t = 2 * static_cast<size_t>(std::max(corner.texcoord_index, 0));
      mesh.uvs.push_back(corner.texcoord_index < 0
                             ? glm::vec2(0.0f)
                             : glm::vec2(attrib_.texcoords[t], attrib_.texcoords[t + 1]));
    }
    glm::vec3 normal(0.0f);
    if (corner.normal_index >= 0) normal = obj_to_blender(attrib_.normals, corner.normal_index);
    // Blender normalises custom normals. Those of unit length to float precision are kept bit
    // for bit so that written files read back exactly; a zero normal counts as missing.
    const double length = glm::length(glm::dvec3(normal));
    if (std::abs(length - 1.0) > 1e-6 && length > 0.0) {
      normal = glm::vec3(glm::dvec3(normal) / length);
    }
    mesh.normals.push_back(normal);
    assembled_.normal_missing.push_back(!(length > 0.0));
  }

  const tinyobj::attrib_t& attrib_;
  bool with_uvs_ = false;
  std::map<std::array<int, 3>, uint32_t> vertex_of_corner_;
  AssembledMesh assembled_;
};

AssembledMesh assemble_mesh(const ObjFile& file, const PartTable& parts) {
  MeshAssembler assembler(file);
  for (size_t s = 0; s < file.shapes.size(); ++s) {
    const std::vector<tinyobj::index_t>& indices = file.shapes[s].mesh.indices;
    for (size_t face = 0; face < parts.face_parts[s].size(); ++face) {
      assembler.add_triangle(&indices[3 * face], parts.face_parts[s][face]);
    }
  }
  return assembler.take();
}

// Normals the file does not give are computed (area-weighted) over all faces that share the
// file position, so that vertices split by a UV seam get the same smooth normal.
void complete_normals(AssembledMesh& assembled, const ObjFile& file) {
  const std::vector<bool>& missing = assembled.normal_missing;
  if (std::find(missing.begin(), missing.end(), true) == missing.end()) return;
  TriangleMesh by_position;
  for (size_t p = 0; p < file.attrib.vertices.size() / 3; ++p) {
    by_position.positions.push_back(obj_to_blender(file.attrib.vertices, static_cast<int>(p)));
  }
  const std::vector<int>& file_positions = assembled.file_positions;
  for (const glm::uvec3& t : assembled.mesh.triangles) {
    by_position.triangles.emplace_back(file_positions[t[0]], file_positions[t[1]],
                                       file_positions[t[2]]);
  }
  compute_vertex_normals(by_position);
  for (size_t v = 0; v < missing.size(); ++v) {
    if (missing[v]) {
      assembled.mesh.normals[v] = by_position.normals[static_cast<size_t>(file_positions[v])];
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Textures

// A texture an MTL material names, and how error messages refer to it.
struct TextureSource {
  std::string name;  // as the .mtl writes it
  fs::path file;
  std::string what;  // "<mtl>: material '<name>' map_Kd"
};

// Decoded with tinygltf's stb_image. Its exported decoder always expands to RGBA (the
// channel-preserving option is internal to tinygltf's implementation), so every texture read
// from an OBJ has 4 channels.
ImagePixels decode_texture(const std::string& obj_path, const TextureSource& source) {
  std::string bytes;
  if (!read_whole_file(source.file, bytes)) {
    fail(obj_path, concat(source.what, ": cannot open texture ", source.file.string()));
  }
  if (bytes.size() > static_cast<size_t>(std::numeric_limits<int>::max())) {
    fail(obj_path, concat(source.what, ": texture ", source.file.string(), " is too large"));
  }
  tinygltf::Image image;
  image.name = source.file.string();
  std::string errors;
  std::string warnings;
  const bool decoded = tinygltf::LoadImageData(&image, 0, &errors, &warnings, 0, 0,
                                               reinterpret_cast<const unsigned char*>(bytes.data()),
                                               static_cast<int>(bytes.size()), nullptr);
  const size_t expected = static_cast<size_t>(image.width) * static_cast<size_t>(image.height) *
                          static_cast<size_t>(image.component) *
                          static_cast<size_t>(image.bits / 8);
  if (!decoded || image.component != 4 || (image.bits != 8 && image.bits != 16) ||
      image.image.size() != expected) {
    fail(obj_path, concat(source.what, ": cannot decode texture ", source.file.string(), " (",
                          trim(errors), ")"));
  }
  ImagePixels pixels;
  pixels.name = source.name;
  pixels.width = image.width;
  pixels.height = image.height;
  pixels.channels = image.component;
  pixels.data = to_8_bit(image);
  return pixels;
}

// Blender feeds a Pr or Pm map's colour to a float socket, which takes its luminance (Rec. 709
// weights, those of Blender's default colour management).
uint8_t luminance(const ImagePixels& rgba, size_t pixel) {
  const uint8_t* p = &rgba.data[4 * pixel];
  return static_cast<uint8_t>((2126u * p[0] + 7152u * p[1] + 722u * p[2] + 5000u) / 10000u);
}

// The decoded textures the asset's materials reference, each decoded once.
class TextureTable {
 public:
  explicit TextureTable(std::string obj_path) : obj_path_(std::move(obj_path)) {}

  int color_texture(const TextureSource& source) {
    const auto found = index_of_file_.find(source.file.string());
    if (found != index_of_file_.end()) return found->second;
    images_.push_back(decode_texture(obj_path_, source));
    const int index = static_cast<int>(images_.size()) - 1;
    index_of_file_.emplace(source.file.string(), index);
    return index;
  }

  // MaterialDesc packs roughness into G and metallic into B of one image (R unused, 0). A
  // channel without a map is 255, so that the material's scalar factor stands for it.
  int metallic_roughness_texture(const TextureSource* roughness, const TextureSource* metallic) {
    const std::pair<std::string, std::string> key(roughness ? roughness->file.string() : "",
                                                  metallic ? metallic->file.string() : "");
    const auto found = index_of_packed_.find(key);
    if (found != index_of_packed_.end()) return found->second;
    images_.push_back(pack_metallic_roughness(roughness, metallic));
    const int index = static_cast<int>(images_.size()) - 1;
    index_of_packed_.emplace(key, index);
    return index;
  }

  std::vector<ImagePixels> take_images() { return std::move(images_); }

 private:
  ImagePixels pack_metallic_roughness(const TextureSource* roughness_source,
                                      const TextureSource* metallic_source) const {
    ImagePixels roughness, metallic;
    if (roughness_source) roughness = decode_texture(obj_path_, *roughness_source);
    if (metallic_source) metallic = decode_texture(obj_path_, *metallic_source);
    if (roughness_source && metallic_source &&
        (roughness.width != metallic.width || roughness.height != metallic.height)) {
      fail(obj_path_, concat(roughness_source->what, " (", roughness.width, "x", roughness.height,
                             ") and map_Pm (", metallic.width, "x", metallic.height,
                             ") differ in size; they cannot be packed into one image"));
    }
    const ImagePixels& shape = roughness_source ? roughness : metallic;
    ImagePixels packed;
    packed.name =
        (roughness_source ? roughness.name : "") + "+" + (metallic_source ? metallic.name : "");
    packed.width = shape.width;
    packed.height = shape.height;
    packed.channels = 3;
    const size_t pixel_count = static_cast<size_t>(shape.width) * static_cast<size_t>(shape.height);
    packed.data.resize(3 * pixel_count);
    for (size_t i = 0; i < pixel_count; ++i) {
      packed.data[3 * i + 1] = roughness_source ? luminance(roughness, i) : 255;
      packed.data[3 * i + 2] = metallic_source ? luminance(metallic, i) : 255;
    }
    return packed;
  }

  std::string obj_path_;
  std::map<std::string, int> index_of_file_;
  std::map<std::pair<std::string, std::string>, int> index_of_packed_;
  std::vector<ImagePixels> images_;
};

// ---------------------------------------------------------------------------------------------
// Materials: MTL to the Principled BSDF as Blender's OBJ importer builds it
// (io/wavefront_obj/importer/obj_import_mtl.cc, set_bsdf_socket_values and add_image_textures).
// Blender 3.4 reads the classic MTL statements; the PBR extension (Pr, Pm, map_Pr, map_Pm) is
// read as Blender 3.5 added it: its values, when given, replace the ones derived from Ns and Ka.
// Not representable in MaterialDesc and ignored: Ke/map_Ke, d/map_d, Ni, Kt, map_Ks, map_Ns,
// refl, disp, sheen, clearcoat, anisotropy, and the texture options -o, -s (Blender adds a
// Mapping node for them) and -type. Blender ignores -clamp, so textures repeat.

struct IllumFlags {
  bool highlight = false;
  bool reflection = false;
};

// Blender: illum 2 turns highlights on, 3 to 8 turn reflection on.
IllumFlags illum_flags(int illum) { return {illum == 2, illum >= 3 && illum <= 8}; }

// Principled inputs are defined on [0, 1]; Blender passes MTL values through, and a base colour
// above 1 would reflect more light than arrives.
double unit_clamp(double value) { return std::clamp(value, 0.0, 1.0); }

double mean3(const tinyobj::real_t* values) {
  return (static_cast<double>(values[0]) + values[1] + values[2]) / 3.0;
}

class MaterialConverter {
 public:
  MaterialConverter(const ObjFile& file, TextureTable& textures)
      : file_(file), textures_(textures) {}

  MaterialDesc convert(size_t index) const {
    const tinyobj::material_t& material = file_.materials[index];
    const std::string what =
        concat(file_.material_libraries[index], ": material '", material.name, "'");
    check_finite_values(material, what);
    MaterialDesc desc = default_material(material.name);
    set_scalars(material, desc);
    set_textures(material, index, what, desc);
    return desc;
  }

 private:
  void check_finite_values(const tinyobj::material_t& material, const std::string& what) const {
    const auto finite3 = [](const tinyobj::real_t* v) {
      return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
    };
    const bool finite = finite3(material.diffuse) && finite3(material.specular) &&
                        finite3(material.ambient) && std::isfinite(material.shininess) &&
                        std::isfinite(material.roughness) && std::isfinite(material.metallic) &&
                        std::isfinite(material.bump_texopt.bump_multiplier) &&
                        std::isfinite(material.normal_texopt.bump_multiplier);
    if (!finite) fail(file_.path, what + ": non-finite value");
  }

  // The -1 "not given" markers come from kNotGivenMarkers.
  static void set_scalars(const tinyobj::material_t& material, MaterialDesc& desc) {
    const IllumFlags illum = illum_flags(material.illum);
    // Base colour: Kd when no component is negative; otherwise Principled's default grey, which
    // default_material already holds.
    const glm::dvec3 kd(material.diffuse[0], material.diffuse[1], material.diffuse[2]);
    if (kd.r >= 0.0 && kd.g >= 0.0 && kd.b >= 0.0) {
      desc.base_color = glm::clamp(kd, glm::dvec3(0.0), glm::dvec3(1.0));
    }
    // Specular: the mean of Ks; without Ks, 1 with highlights and 0 otherwise.
    const double ks = mean3(material.specular);
    desc.specular = ks >= 0.0 ? unit_clamp(ks) : (illum.highlight ? 1.0 : 0.0);
    // Roughness: Pr; otherwise 1 - sqrt(Ns / 1000) with Ns clamped to [0, 1000]; without Ns,
    // 0 with highlights and 1 otherwise.
    if (material.roughness >= 0.0f) {
      desc.roughness = unit_clamp(material.roughness);
    } else if (material.shininess >= 0.0f) {
      desc.roughness =
          1.0 - std::sqrt(std::clamp<double>(material.shininess, 0.0, 1000.0) / 1000.0);
    } else {
      desc.roughness = illum.highlight ? 0.0 : 1.0;
    }
    // Metallic: Pm; otherwise for reflecting illum models the mean of Ka (1 without Ka), and 0
    // for all others -- OBJ materials are dielectric unless they say otherwise, unlike glTF's.
    const double ka = mean3(material.ambient);
    if (material.metallic >= 0.0f) {
      desc.metallic = unit_clamp(material.metallic);
    } else {
      desc.metallic = illum.reflection ? (ka >= 0.0 ? unit_clamp(ka) : 1.0) : 0.0;
    }
  }

  // A connected Image Texture replaces the socket value in Blender, so an input with a map has
  // factor 1 (for metallic-roughness only the mapped channel has, see TextureTable).
  void set_textures(const tinyobj::material_t& material, size_t index, const std::string& what,
                    MaterialDesc& desc) const {
    if (!material.diffuse_texname.empty()) {
      desc.base_color_image =
          textures_.color_texture(source(material.diffuse_texname, index, what + " map_Kd"));
      desc.base_color = glm::dvec3(1.0);
    }
    set_metallic_roughness_texture(material, index, what, desc);
    set_normal_texture(material, index, what, desc);
  }

  void set_metallic_roughness_texture(const tinyobj::material_t& material, size_t index,
                                      const std::string& what, MaterialDesc& desc) const {
    const bool has_roughness = !material.roughness_texname.empty();
    const bool has_metallic = !material.metallic_texname.empty();
    if (!has_roughness && !has_metallic) return;
    const TextureSource roughness = source(material.roughness_texname, index, what + " map_Pr");
    const TextureSource metallic = source(material.metallic_texname, index, what + " map_Pm");
    desc.metallic_roughness_image = textures_.metallic_roughness_texture(
        has_roughness ? &roughness : nullptr, has_metallic ? &metallic : nullptr);
    if (has_roughness) desc.roughness = 1.0;
    if (has_metallic) desc.metallic = 1.0;
  }

  // Blender connects map_Bump (or bump) through a Normal Map node: it is a tangent-space normal
  // map, not a height map, with strength max(0, -bm). Blender ignores "norm", the PBR
  // extension's normal map, which is read here when map_Bump is absent. Without -bm Blender 3.4
  // leaves its -1 marker, making the strength 0 and the map invisible; the MTL default -bm 1
  // (tinyobjloader's) is kept instead.
  void set_normal_texture(const tinyobj::material_t& material, size_t index,
                          const std::string& what, MaterialDesc& desc) const {
    const bool bump = !material.bump_texname.empty();
    if (!bump && material.normal_texname.empty()) return;
    const TextureSource normal = bump ? source(material.bump_texname, index, what + " map_Bump")
                                      : source(material.normal_texname, index, what + " norm");
    desc.normal_image = textures_.color_texture(normal);
    const tinyobj::texture_option_t& options = bump ? material.bump_texopt : material.normal_texopt;
    desc.normal_strength = std::max(0.0, static_cast<double>(options.bump_multiplier));
  }

  // Texture paths are relative to the .mtl's directory (Blender's first choice; its fallbacks
  // for broken exports are not tried). Blender drops quotes from them.
  TextureSource source(std::string name, size_t index, const std::string& what) const {
    name.erase(std::remove(name.begin(), name.end(), '"'), name.end());
    const fs::path library(file_.material_libraries[index]);
    return {name, library.parent_path() / name, what};
  }

  const ObjFile& file_;
  TextureTable& textures_;
};

// ---------------------------------------------------------------------------------------------
// Assembly of the asset

// Every part's MaterialDesc, each file material converted once.
std::vector<MaterialDesc> part_materials(const ObjFile& file, const PartTable& parts,
                                         std::vector<ImagePixels>& images) {
  TextureTable textures(file.path);
  const MaterialConverter converter(file, textures);
  std::map<int, MaterialDesc> converted;
  std::vector<MaterialDesc> materials;
  for (const int material : parts.materials) {
    auto found = converted.find(material);
    if (found == converted.end()) {
      const MaterialDesc desc =
          material < 0 ? default_material() : converter.convert(static_cast<size_t>(material));
      found = converted.emplace(material, desc).first;
    }
    materials.push_back(found->second);
  }
  images = textures.take_images();
  return materials;
}

void check_file_values(const ObjFile& file) {
  check_finite(file.path, file.attrib.vertices, 3, "position");
  check_finite(file.path, file.attrib.normals, 3, "normal");
  check_finite(file.path, file.attrib.texcoords, 2, "texture coordinate");
  check_indices(file);
}

// ---------------------------------------------------------------------------------------------
// Writing

// Names in OBJ and MTL end at whitespace (tinyobjloader's "usemtl" and "g" read one word,
// Blender trims), so blanks and control characters become '_'; an empty name becomes `fallback`.
std::string obj_safe_name(const std::string& name, const std::string& fallback) {
  if (name.empty()) return fallback;
  std::string safe = name;
  for (char& c : safe) {
    const unsigned char byte = static_cast<unsigned char>(c);
    if (byte <= ' ' || byte == 0x7f) c = '_';
  }
  return safe;
}

// Hands out names no earlier call returned, appending _2, _3... to repeats.
class UniqueNames {
 public:
  std::string claim(const std::string& wanted) {
    std::string name = wanted;
    for (int suffix = 2; taken_.count(name) != 0; ++suffix) name = concat(wanted, "_", suffix);
    taken_.insert(name);
    return name;
  }

 private:
  std::set<std::string> taken_;
};

// Nine significant digits identify every float, so positions, normals and UVs read back exactly.
std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.9g", value);
  return text;
}

std::string triple(const glm::dvec3& v) {
  return number(v.x) + " " + number(v.y) + " " + number(v.z);
}

// Blender's +Z up to OBJ's +Y up, the inverse of obj_to_blender.
glm::dvec3 blender_to_obj(const glm::vec3& v) { return {v.x, v.z, -v.y}; }

void check_image(const ObjectAsset& asset, int image, const MaterialDesc& material) {
  if (image < 0) return;
  if (static_cast<size_t>(image) >= asset.images.size()) {
    throw std::invalid_argument(concat("write_obj: material '", material.name, "' refers to image ",
                                       image, " but the asset has ", asset.images.size()));
  }
  const ImagePixels& pixels = asset.images[static_cast<size_t>(image)];
  const size_t expected = static_cast<size_t>(std::max(pixels.width, 0)) *
                          static_cast<size_t>(std::max(pixels.height, 0)) *
                          static_cast<size_t>(std::max(pixels.channels, 0));
  if (pixels.width <= 0 || pixels.height <= 0 || pixels.channels < 1 || pixels.channels > 4 ||
      pixels.data.size() != expected) {
    throw std::invalid_argument(concat("write_obj: image ", image, " (", pixels.name,
                                       ") has inconsistent size or channels"));
  }
}

void check_writable(const ObjectAsset& asset) {
  validate_mesh(asset.mesh, "write_obj");
  if (asset.mesh.triangles.empty())
    throw std::invalid_argument("write_obj: the mesh has no triangles");
  if (asset.materials.size() < asset.mesh.part_count()) {
    throw std::invalid_argument(concat("write_obj: ", asset.mesh.part_count(), " parts but ",
                                       asset.materials.size(), " materials"));
  }
  for (const MaterialDesc& material : asset.materials) {
    const std::vector<double> values = {
        material.base_color.r, material.base_color.g, material.base_color.b,   material.specular,
        material.roughness,    material.metallic,     material.normal_strength};
    if (!std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); })) {
      throw std::invalid_argument("write_obj: material '" + material.name +
                                  "' has a non-finite value");
    }
    for (const int image :
         {material.base_color_image, material.metallic_roughness_image, material.normal_image}) {
      check_image(asset, image, material);
    }
  }
}

// One channel of every pixel as a grey image; grey and grey-alpha images give their grey.
ImagePixels channel_image(const ImagePixels& image, int channel) {
  const size_t source_channel = image.channels < 3 ? 0 : static_cast<size_t>(channel);
  const size_t channels = static_cast<size_t>(image.channels);
  ImagePixels grey;
  grey.width = image.width;
  grey.height = image.height;
  grey.channels = 1;
  grey.data.resize(image.data.size() / channels);
  for (size_t i = 0; i < grey.data.size(); ++i)
    grey.data[i] = image.data[i * channels + source_channel];
  return grey;
}

// A written PNG: its file name beside the .obj and its pixels.
struct ImageFile {
  std::string name;
  ImagePixels pixels;
};

// The file names of a material's maps ("" for none).
struct MaterialMaps {
  std::string base_color, roughness, metallic, normal;
};

// The PNG files the materials need, each asset image written once: base colour and normal
// images as they are; a metallic-roughness image split into the grey map_Pr (its G) and map_Pm
// (its B) that MTL has instead.
class ImageFiles {
 public:
  ImageFiles(const std::vector<ImagePixels>& images, std::string stem)
      : images_(images), stem_(std::move(stem)) {}

  MaterialMaps maps_of(const MaterialDesc& material) {
    MaterialMaps maps;
    if (material.base_color_image >= 0) maps.base_color = image_file(material.base_color_image);
    if (material.normal_image >= 0) maps.normal = image_file(material.normal_image);
    if (material.metallic_roughness_image >= 0) {
      maps.roughness = channel_file(material.metallic_roughness_image, 1, "roughness");
      maps.metallic = channel_file(material.metallic_roughness_image, 2, "metallic");
    }
    return maps;
  }

  const std::vector<ImageFile>& files() const { return files_; }

 private:
  std::string image_file(int image) {
    return add(concat(stem_, "_image", image, ".png"), images_[static_cast<size_t>(image)]);
  }

  std::string channel_file(int image, int channel, const char* what) {
    const std::string name = concat(stem_, "_image", image, "_", what, ".png");
    if (written_.count(name) != 0) return name;
    return add(name, channel_image(images_[static_cast<size_t>(image)], channel));
  }

  std::string add(const std::string& name, const ImagePixels& pixels) {
    if (written_.insert(name).second) files_.push_back({name, pixels});
    return name;
  }

  const std::vector<ImagePixels>& images_;
  std::string stem_;
  std::set<std::string> written_;
  std::vector<ImageFile> files_;
};

bool capture_file(std::string*, const std::string&, const std::vector<unsigned char>& contents,
                  void* destination) {
  static_cast<std::vector<unsigned char>*>(destination)->assign(contents.begin(), contents.end());
  return true;
}

// PNG bytes from tinygltf's stb_image_write, captured by a WriteWholeFile callback instead of
// written, so that the file is staged like the others.
std::string encode_png(const ImagePixels& pixels, const std::string& path) {
  tinygltf::Image image;
  image.width = pixels.width;
  image.height = pixels.height;
  image.component = pixels.channels;
  image.bits = 8;
  image.pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
  image.image = pixels.data;
  std::vector<unsigned char> png;
  tinygltf::FsCallbacks callbacks = {};
  callbacks.WriteWholeFile = capture_file;
  callbacks.user_data = &png;
  const std::string base_directory;
  const std::string file_name = "image.png";  // the extension selects the encoder
  std::string uri;
  if (!tinygltf::WriteImageData(&base_directory, &file_name, &image, /*embedImages=*/false, &uri,
                                &callbacks) ||
      png.empty()) {
    fail(path, "cannot encode image " + pixels.name + " as PNG");
  }
  return std::string(png.begin(), png.end());
}

// Materials in the order of the asset, with MTL-safe unique names and their map files.
struct NamedMaterial {
  std::string name;
  const MaterialDesc* desc;
  MaterialMaps maps;
};

// The inverse of MaterialConverter. read_obj, like Blender, lets a map replace its factor, so a
// factor other than 1 beside a map does not survive a round trip (it is still written, for
// readers that multiply). MaterialDesc's wrap, specular tint and label id are not written:
// Blender's importer reads no MTL statement for them.
std::string mtl_text(const std::vector<NamedMaterial>& materials) {
  std::string text = "# matpredict\n";
  for (const NamedMaterial& material : materials) {
    const MaterialDesc& desc = *material.desc;
    text += "\nnewmtl " + material.name + "\n";
    text += "Kd " + triple(desc.base_color) + "\n";
    text += "Ks " + triple(glm::dvec3(desc.specular)) + "\n";
    // For readers without the PBR extension (Blender before 3.5): Ns inverts Blender's
    // roughness = 1 - sqrt(Ns / 1000), and under illum 3 Blender's metallic is the mean of Ka.
    text += "Ns " + number(1000.0 * (1.0 - desc.roughness) * (1.0 - desc.roughness)) + "\n";
    text += "Ka " + triple(glm::dvec3(desc.metallic)) + "\n";
    text += desc.metallic > 0.0 ? "illum 3\n" : "illum 2\n";
    text += "Pr " + number(desc.roughness) + "\n";
    text += "Pm " + number(desc.metallic) + "\n";
    const MaterialMaps& maps = material.maps;
    if (!maps.base_color.empty()) text += "map_Kd " + maps.base_color + "\n";
    if (!maps.roughness.empty()) text += "map_Pr " + maps.roughness + "\n";
    if (!maps.metallic.empty()) text += "map_Pm " + maps.metallic + "\n";
    if (!maps.normal.empty()) {
      text += "map_Bump -bm " + number(desc.normal_strength) + " " + maps.normal + "\n";
    }
  }
  return text;
}

// tinyobjloader splits "mtllib" at spaces and takes '\' as an escape.
std::string escaped_library_name(const std::string& name) {
  std::string escaped;
  for (const char c : name) {
    if (c == ' ' || c == '\\') escaped += '\\';
    escaped += c;
  }
  return escaped;
}

// Corner reference "v", "v/vt", "v//vn" or "v/vt/vn"; every attribute shares the vertex's index.
std::string corner_reference(uint32_t vertex, bool uvs, bool normals) {
  const std::string index = std::to_string(vertex + 1);
  if (!uvs && !normals) return index;
  return index + "/" + (uvs ? index : "") + (normals ? "/" + index : "");
}

std::string obj_text(const TriangleMesh& mesh, const std::string& library,
                     const std::vector<std::string>& group_names,
                     const std::vector<NamedMaterial>& materials) {
  std::ostringstream text;
  text << "# matpredict\nmtllib " << escaped_library_name(library) << "\n";
  for (const glm::vec3& p : mesh.positions) text << "v " << triple(blender_to_obj(p)) << "\n";
  for (const glm::vec2& uv : mesh.uvs) text << "vt " << number(uv.x) << " " << number(uv.y) << "\n";
  for (const glm::vec3& n : mesh.normals) text << "vn " << triple(blender_to_obj(n)) << "\n";

  std::vector<std::vector<size_t>> triangles_of_part(group_names.size());
  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    triangles_of_part[mesh.triangle_parts.empty() ? 0 : mesh.triangle_parts[t]].push_back(t);
  }
  const bool uvs = !mesh.uvs.empty(), normals = !mesh.normals.empty();
  for (size_t part = 0; part < group_names.size(); ++part) {
    // A part without triangles would leave only an empty group, which readers drop anyway.
    if (triangles_of_part[part].empty()) continue;
    text << "g " << group_names[part] << "\nusemtl " << materials[part].name << "\n";
    for (const size_t t : triangles_of_part[part]) {
      const glm::uvec3& triangle = mesh.triangles[t];
      text << "f " << corner_reference(triangle[0], uvs, normals) << " "
           << corner_reference(triangle[1], uvs, normals) << " "
           << corner_reference(triangle[2], uvs, normals) << "\n";
    }
  }
  return text.str();
}


}  // namespace

ObjectAsset read_obj(const std::string& path, const ObjReadOptions& options) {
  const ObjFile file = load_obj(path);
  check_file_values(file);
  const PartTable parts = options.parts_from == ObjReadOptions::PartsFrom::Material
                              ? parts_by_material(file)
                              : parts_by_group(file);

  AssembledMesh assembled = assemble_mesh(file, parts);
  if (assembled.mesh.triangles.empty()) fail(path, "no faces with a surface");
  complete_normals(assembled, file);

  ObjectAsset asset;
  asset.mesh = std::move(assembled.mesh);
  // Tangents serve normal maps, which need UVs (as in read_gltf).
  if (!asset.mesh.uvs.empty()) compute_tangents(asset.mesh);
  asset.mesh.part_names = parts.names;
  asset.materials = part_materials(file, parts, asset.images);
  try {
    validate_mesh(asset.mesh, "read_obj");
  } catch (const std::invalid_argument& error) {
    fail(path, error.what());
  }
  return asset;
}

void write_obj(const ObjectAsset& asset, const std::string& path) {
  check_writable(asset);
  const TriangleMesh& mesh = asset.mesh;
  const fs::path obj_path(path);
  const std::string stem = obj_path.stem().string();
  if (std::any_of(stem.begin(), stem.end(), [](char c) { return c == '\n' || c == '\r'; })) {
    throw std::invalid_argument("write_obj: " + path +
                                ": \"mtllib\" cannot name a file with a line break");
  }

  ImageFiles images(asset.images, stem);
  UniqueNames material_names;
  UniqueNames group_names;
  std::vector<NamedMaterial> materials;
  std::vector<std::string> groups;
  for (uint32_t part = 0; part < mesh.part_count(); ++part) {
    const MaterialDesc& desc = asset.materials[part];
    materials.push_back(
        {material_names.claim(obj_safe_name(desc.name, "material")), &desc, images.maps_of(desc)});
    // Groups take the part's name, or else its material's.
    const std::string part_name = part < mesh.part_names.size() ? mesh.part_names[part] : "";
    groups.push_back(group_names.claim(
        obj_safe_name(part_name.empty() ? desc.name : part_name, concat("part", part))));
  }

  const std::string library = stem + ".mtl";
  // Written together, the .obj last, so that no reader finds an .obj whose .mtl or textures are
  // missing.
  AtomicFileSet files(path);
  for (const ImageFile& image : images.files()) {
    files.stage(obj_path.parent_path() / image.name, encode_png(image.pixels, path));
  }
  files.stage(obj_path.parent_path() / library, mtl_text(materials));
  files.stage(obj_path, obj_text(mesh, library, groups, materials));
  files.commit();
}

}  // namespace matgeom
