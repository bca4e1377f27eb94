#include "matgeom/io/mesh_io.h"

#include <filesystem>
#include <stdexcept>

#include "matbase/file/input_file.h"
#include "matbase/text.h"
#include "matgeom/io/gltf/gltf_reader.h"
#include "matgeom/io/gltf/gltf_writer.h"
#include "matgeom/io/obj/obj_io.h"
#include "matgeom/io/ply/ply_io.h"

namespace matgeom {
namespace {

std::string unsupported(const std::string& path) {
  return path + ": unsupported file type \"" + matbase::lowercase_extension(path) + "\" (expected .glb, .gltf, .ply or .obj)";
}

}  // namespace

const std::vector<std::string>& object_file_extensions() {
  static const std::vector<std::string> extensions = {".glb", ".gltf", ".ply", ".obj"};
  return extensions;
}

ObjectAsset read_object(const std::string& path, const ObjectReadOptions& options) {
  matbase::require_input_file(path);
  const std::string extension = matbase::lowercase_extension(path);
  if (extension == ".glb" || extension == ".gltf") return read_gltf(path, {options.auto_smooth_deg});
  if (extension == ".obj") {
    ObjReadOptions obj_options;
    obj_options.auto_smooth_deg = options.auto_smooth_deg;
    return read_obj(path, obj_options);
  }
  if (extension != ".ply") throw std::runtime_error(unsupported(path));
  PlyReadOptions ply_options;
  ply_options.auto_smooth_deg = options.auto_smooth_deg;
  ObjectAsset asset;
  asset.mesh = read_ply(path, ply_options);
  for (uint32_t part = 0; part < asset.mesh.part_count(); ++part) {
    matmaterial::MaterialInputs material(part < asset.mesh.part_names.size() ? asset.mesh.part_names[part] : "default");
    // A scan's colours are its surface: the base colour is theirs.
    if (!asset.mesh.colors.empty()) {
      material.set(matmaterial::MaterialParameter::BaseColor, 1.0);
      material.vertex_colors = true;
    }
    asset.materials.push_back(std::move(material));
  }
  if (!asset.mesh.colors.empty())
    add_note(asset.notes, "the vertex colours are the base colour of every part (Blender's PLY importer keeps them "
                          "as a colour attribute that no material reads)");
  return asset;
}

void write_object(const ObjectAsset& asset, const std::string& path) {
  const std::string extension = matbase::lowercase_extension(path);
  if (extension == ".glb" || extension == ".gltf") return write_gltf(asset, path);
  if (extension == ".obj") return write_obj(asset, path);
  if (extension == ".ply") return write_ply(asset.mesh, path);
  throw std::invalid_argument(unsupported(path));
}

}  // namespace matgeom
