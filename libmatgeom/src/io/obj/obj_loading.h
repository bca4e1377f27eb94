#pragma once
// Loading: an OBJ file and its .mtl files parsed and triangulated by tinyobjloader, and the
// checks on what tinyobjloader returns (finite values, indices in range, triangles).
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
  std::vector<std::string> notes;  // what the reader does not apply as written (ObjectAsset::notes)
};

ObjFile load_obj(const std::string& path);

void check_file_values(const ObjFile& file);

}  // namespace matgeom::obj
