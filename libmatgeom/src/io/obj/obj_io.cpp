#include "matgeom/io/obj/obj_io.h"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <utility>
#include <vector>

#include "matbase/file/atomic_file.h"
#include "matbase/file/file_error.h"
#include "matbase/image/png_encoding.h"
#include "matgeom/tangents.h"
#include "io/obj/mtl_materials.h"
#include "io/obj/obj_loading.h"
#include "io/obj/obj_parts.h"
#include "io/obj/obj_writing.h"

// Reading is four steps: the OBJ text is screened for the inputs tinyobjloader 2.0.0rc10 handles
// badly; tinyobjloader parses and triangulates it, reading every "mtllib" through
// MaterialLibraries, which screens each .mtl and marks what each material leaves out; the faces become one vertex per
// distinct v/vt/vn triple with a part per material slot or group; the used MTL materials become
// MaterialDescs as Blender's OBJ importer builds its Principled BSDF. Writing is done by hand.
//
// Axes: OBJ files are +Y up. As in Blender's importer with its default axes (forward -Z, up Y),
// (x, y, z) in the file is (x, -z, y) in Blender's +Z up frame; write_obj converts back.
// UVs need no conversion: OBJ's v points up the image, as Blender's does.

namespace matgeom {

namespace fs = std::filesystem;

ObjectAsset read_obj(const std::string& path, const ObjReadOptions& options) {
  const obj::ObjFile file = obj::load_obj(path);
  obj::check_file_values(file);
  const obj::PartTable parts = options.parts_from == ObjReadOptions::PartsFrom::Material
                                   ? obj::parts_by_material(file)
                                   : obj::parts_by_group(file);

  obj::AssembledMesh assembled = obj::assemble_mesh(file, parts);
  if (assembled.mesh.triangles.empty()) matbase::fail(path, "no faces with a surface");
  obj::complete_normals(assembled, options.auto_smooth_deg);

  ObjectAsset asset;
  asset.mesh = std::move(assembled.mesh);
  // Tangents serve normal maps, which need UVs (as in read_gltf); a flat mesh has no vertex
  // normal to build them on, and gets them when a normal map needs them (matrender's scene).
  if (!asset.mesh.uvs.empty() && !asset.mesh.normals.empty()) compute_tangents(asset.mesh);
  asset.mesh.part_names = parts.names;
  asset.notes = file.notes;
  asset.materials = obj::part_materials(file, parts, asset.images, asset.notes);
  try {
    validate_mesh(asset.mesh, "read_obj");
  } catch (const std::invalid_argument& error) {
    matbase::fail(path, error.what());
  }
  return asset;
}

void write_obj(const ObjectAsset& asset, const std::string& path) {
  obj::check_writable(asset);
  const TriangleMesh& mesh = asset.mesh;
  const fs::path obj_path(path);
  const std::string stem = obj_path.stem().string();
  if (std::any_of(stem.begin(), stem.end(), [](char c) { return c == '\n' || c == '\r'; })) {
    throw std::invalid_argument("write_obj: " + path +
                                ": \"mtllib\" cannot name a file with a line break");
  }

  obj::ImageFiles images(asset.images, stem);
  obj::UniqueNames material_names;
  obj::UniqueNames group_names;
  std::vector<obj::NamedMaterial> materials;
  std::vector<std::string> groups;
  for (uint32_t part = 0; part < mesh.part_count(); ++part) {
    const matmaterial::MaterialInputs& desc = asset.materials[part];
    materials.push_back({material_names.claim(obj::obj_safe_name(desc.name, "material")), &desc,
                         images.maps_of(desc)});
    // Groups take the part's name, or else its material's.
    const std::string part_name = part < mesh.part_names.size() ? mesh.part_names[part] : "";
    groups.push_back(group_names.claim(
        obj::obj_safe_name(part_name.empty() ? desc.name : part_name, matbase::concat("part", part))));
  }

  const std::string library = stem + ".mtl";
  // Written together, the .obj last, so that no reader finds an .obj whose .mtl or textures are
  // missing.
  matbase::AtomicFileSet files(path);
  for (const obj::ImageFile& image : images.files()) {
    files.stage(obj_path.parent_path() / image.name, matbase::encode_png(image.pixels, path));
  }
  files.stage(obj_path.parent_path() / library, obj::mtl_text(materials));
  files.stage(obj_path, obj::obj_text(mesh, library, groups, materials));
  files.commit();
}

}  // namespace matgeom
