#include "io/obj/obj_loading.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <sstream>
#include <string_view>
#include <utility>
#include <vector>

#include "matbase/file/file_error.h"
#include "matbase/file/input_file.h"
#include "matbase/text.h"
#include "matbase/text_encoding.h"
#include "io/obj/material_names.h"
#include "io/obj/mtl_text_screening.h"
#include "io/obj/obj_text_screening.h"
#include "io/obj/statement_text.h"

namespace matgeom::obj {

namespace fs = std::filesystem;

// ---------------------------------------------------------------------------------------------
// Loading

namespace {

// OBJ and MTL text saved as UTF-16 or UTF-32 (Windows' "Unicode"), or with a UTF-8 byte-order
// mark, read as UTF-8 (Blender 3.4 reads UTF-16 as garbage and says nothing).
std::string marked_text_as_utf8(const std::string& where, const std::string& bytes) {
  std::string text;
  if (const std::optional<std::string> problem = matbase::decode_marked_text(bytes, text)) matbase::fail(where, *problem);
  return text;
}

// What a "usemtl" naming no material it can use is missing, for its error message.
std::string missing_material_reason(const ObjFile& file, const std::string& name) {
  const auto defined = [&](const tinyobj::material_t& m) { return m.name == name; };
  if (std::any_of(file.materials.begin(), file.materials.end(), defined))
    return "its material library is named by an \"mtllib\" after this line";
  // tinyobjloader adds an unnamed material for a library without "newmtl".
  std::vector<std::string> names;
  for (const tinyobj::material_t& m : file.materials)
    if (!m.name.empty()) names.push_back(m.name);
  if (names.empty()) return "no material library defines any material";
  std::string listed;
  const size_t shown = std::min<size_t>(names.size(), 10);
  for (size_t m = 0; m < shown; ++m) listed += (m == 0 ? "" : ", ") + matbase::excerpt(names[m]);
  if (shown < names.size()) listed += matbase::concat(" and ", names.size() - shown, " more");
  return "its material libraries define " + listed;
}

// tinyobjloader gives the faces after a "usemtl" whose material no library read so far defines
// no material, with only a warning; such a file is refused, at the first line using the name. An
// OBJ that names no library at all (exported without its .mtl) is read with the default
// material, as Blender gives it empty materials of those names: no name there can be a typo.
void check_material_uses(const ObjFile& file, const std::string& text) {
  constexpr std::string_view kBefore = "material [ '", kAfter = "' ] not found in .mtl";
  const size_t found = file.warnings.find(kBefore);
  if (found == std::string::npos || !names_material_library(text)) return;
  const size_t begin = found + kBefore.size();
  const std::string name = word_name(file.warnings.substr(begin, file.warnings.find(kAfter, begin) - begin));
  matbase::fail(file.path, matbase::concat("line ", first_use_line(text, name), ": usemtl ", matbase::excerpt(name),
                         ": no such material (", missing_material_reason(file, name), ")"));
}

// Reads the .mtl files "mtllib" names for tinyobjloader, screened, remembering the file each
// material comes from and the files that could not be read (tinyobjloader would only warn about
// those). A name is the whole rest of the "mtllib" line (tinyobj_text spells it as one word), a
// file relative to the OBJ's folder, as Blender reads it; when no such file exists, each of its
// blank-separated words is one (the MTL spec's list), and when none of those exists either, the
// .mtl of the OBJ's own stem beside it stands in, as Blender and assimp read it.
class MaterialLibraries : public tinyobj::MaterialReader {
 public:
  explicit MaterialLibraries(std::string obj_path)
      : obj_path_(std::move(obj_path)), obj_directory_(fs::path(obj_path_).parent_path()) {}

  bool operator()(const std::string& word, std::vector<tinyobj::material_t>* materials,
                  std::map<std::string, int>* material_map, std::string* warnings,
                  std::string* errors) override {
    const std::string library = word_name(word);
    std::vector<fs::path> files = {obj_directory_ / library};
    if (!exists(files.front())) {
      files.clear();
      for (const std::string_view listed : split_words(library))
        if (exists(obj_directory_ / listed)) files.push_back(obj_directory_ / listed);
    }
    if (files.empty() && loaded(stem_library())) return true;  // the stand-in is read already
    if (files.empty() && exists(stem_library())) files.push_back(stem_library());
    if (files.empty()) {
      missing_.push_back((obj_directory_ / library).string());
      return false;
    }
    for (const fs::path& file : files) load(file, materials, material_map, warnings, errors);
    return true;
  }

  // The .mtl beside the OBJ with its stem, which Blender reads for an OBJ that names none.
  fs::path stem_library() const { return fs::path(obj_path_).replace_extension(".mtl"); }

  const std::vector<std::string>& sources() const { return sources_; }
  const std::vector<std::string>& missing() const { return missing_; }
  const std::vector<std::string>& notes() const { return notes_; }

 private:
  static bool exists(const fs::path& file) { return !matbase::input_file_problem(file.string()); }
  bool loaded(const fs::path& file) const {
    return std::find(loaded_.begin(), loaded_.end(), file) != loaded_.end();
  }

  void load(const fs::path& file, std::vector<tinyobj::material_t>* materials, std::map<std::string, int>* material_map,
            std::string* warnings, std::string* errors) {
    if (loaded(file)) return;
    loaded_.push_back(file);
    std::string text;
    if (const std::optional<std::string> problem = matbase::read_whole_file(file, text))
      matbase::fail(obj_path_, file.string() + ": " + *problem);
    text = marked_text_as_utf8(obj_path_ + ": " + file.string(), text);
    std::istringstream stream(with_not_given_markers(screened_mtl_text(obj_path_, file.string(), text, notes_)));
    const size_t first = materials->size();
    tinyobj::LoadMtl(material_map, materials, &stream, warnings, errors);
    for (size_t m = first; m < materials->size(); ++m) (*materials)[m].name = word_name((*materials)[m].name);
    sources_.resize(materials->size(), file.string());
  }

  std::string obj_path_;
  fs::path obj_directory_;
  std::vector<fs::path> loaded_;
  std::vector<std::string> sources_;  // the .mtl file of material k
  std::vector<std::string> missing_;
  std::vector<std::string> notes_;
};

}  // namespace

ObjFile load_obj(const std::string& path) {
  std::string text;
  if (const std::optional<std::string> problem = matbase::read_whole_file(path, text)) matbase::fail(path, *problem);
  text = marked_text_as_utf8(path, text);
  screen_obj_text(path, text);

  ObjFile file;
  file.path = path;
  MaterialLibraries libraries(path);
  std::string prepared = tinyobj_text(text);
  // Blender reads the .mtl of the OBJ's stem for an OBJ that names no library.
  if (!names_material_library(text) && !matbase::input_file_problem(libraries.stem_library().string()))
    prepared = "mtllib " + name_word(libraries.stem_library().filename().string()) + "\n" + prepared;
  std::istringstream stream(prepared);
  std::string errors;
  const bool parsed = tinyobj::LoadObj(&file.attrib, &file.shapes, &file.materials, &file.warnings,
                                       &errors, &stream, &libraries, /*triangulate=*/true,
                                       /*default_vcols_fallback=*/false);
  if (!libraries.missing().empty()) {
    matbase::fail(path, "cannot open material library " + libraries.missing().front() + " (nor " +
                            libraries.stem_library().filename().string() + " beside the OBJ)");
  }
  if (!parsed || !errors.empty()) matbase::fail(path, "tinyobjloader: " + matbase::trim(errors));
  file.material_libraries = libraries.sources();
  file.notes = libraries.notes();
  check_material_uses(file, text);
  return file;
}

// ---------------------------------------------------------------------------------------------
// Checks on what tinyobjloader returns: the screening reports bad numbers and indices as the file
// writes them, with their line; these hold the arrays safe from any value tinyobjloader's own
// parsing makes differently (its decimal arithmetic reads 0e999 as 0 x inf, a NaN).

namespace {

void check_finite(const std::string& path, const std::vector<tinyobj::real_t>& values,
                  size_t components, const char* what) {
  for (size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) matbase::fail(path, matbase::concat("non-finite ", what, " ", i / components + 1));
  }
}

// tinyobjloader resolves relative indices but does not range-check them; -1 means "none" for
// texture coordinates and normals. (A relative index resolving to exactly -1 is therefore
// indistinguishable from none.)
void check_index(const std::string& path, int index, size_t count, bool optional,
                 const char* what) {
  if (optional && index == -1) return;
  if (index >= 0 && static_cast<size_t>(index) < count) return;
  matbase::fail(path, matbase::concat("face index out of range: ", what, " ", static_cast<long long>(index) + 1,
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
    matbase::fail(file.path, "face index out of range (tinyobjloader: " + matbase::trim(line) + ")");
  }
}

void check_indices(const ObjFile& file) {
  const tinyobj::attrib_t& attrib = file.attrib;
  for (const tinyobj::shape_t& shape : file.shapes) {
    // Triangulation leaves three corners per face.
    if (shape.mesh.indices.size() != 3 * shape.mesh.material_ids.size()) {
      matbase::fail(file.path, "tinyobjloader returned faces that are not triangles");
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

}  // namespace

void check_file_values(const ObjFile& file) {
  check_finite(file.path, file.attrib.vertices, 3, "position");
  check_finite(file.path, file.attrib.normals, 3, "normal");
  check_finite(file.path, file.attrib.texcoords, 2, "texture coordinate");
  check_indices(file);
}

}  // namespace matgeom::obj
