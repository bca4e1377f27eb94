#pragma once
// Loading: an OBJ file and its .mtl files parsed and triangulated by tinyobjloader, and the
// checks on what tinyobjloader returns (finite values, indices in range, triangles).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <tiny_obj_loader.h>

namespace matgeom::obj {

struct ObjFile {
  std::string path;
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::vector<std::string> material_libraries;  // the .mtl file of material k
  std::string warnings;
};

// Reads the whole file into `bytes`; returns why it could not (matgeom/input_file.h's problems,
// or a failed read), or nothing.
std::optional<std::string> read_whole_file(const std::filesystem::path& file, std::string& bytes);

ObjFile load_obj(const std::string& path);

void check_file_values(const ObjFile& file);

}  // namespace matgeom::obj
