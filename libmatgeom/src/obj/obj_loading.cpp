#include "obj/obj_loading.h"

#include <cmath>
#include <cstddef>
#include <map>
#include <sstream>
#include <utility>

#include "file_error.h"
#include "matgeom/input_file.h"
#include "matgeom/text.h"
#include "obj/obj_text_screening.h"

namespace matgeom::obj {

namespace fs = std::filesystem;

// ---------------------------------------------------------------------------------------------
// Loading

namespace {

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
    if (read_whole_file(file, text)) {
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

}  // namespace

ObjFile load_obj(const std::string& path) {
  std::string text;
  if (const std::optional<std::string> problem = read_whole_file(path, text)) fail(path, *problem);
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

namespace {

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

}  // namespace

void check_file_values(const ObjFile& file) {
  check_finite(file.path, file.attrib.vertices, 3, "position");
  check_finite(file.path, file.attrib.normals, 3, "normal");
  check_finite(file.path, file.attrib.texcoords, 2, "texture coordinate");
  check_indices(file);
}

}  // namespace matgeom::obj
