#include "matrender/scene_builder.h"

#include <algorithm>
#include <exception>
#include <map>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "matgeom/builtin/builtin_objects.h"
#include "matgeom/camera_grid.h"
#include "matgeom/io/mesh_io.h"
#include "matgeom/mesh.h"
#include "matgeom/mesh_parts.h"
#include "matgeom/uv/uv_pass.h"
#include "matrender/asset.h"
#include "matrender/paper_setup.h"
#include "matrender/scene_limits.h"
#include "matrender/scene_materials.h"
#include "matrender/texture.h"

namespace matrender {
namespace {

std::string quoted_part_names(const matgeom::TriangleMesh& mesh) {
  std::string names;
  for (const std::string& name : mesh.part_names) names += (names.empty() ? "\"" : ", \"") + name + "\"";
  return names.empty() ? "its parts have no names" : "its parts: " + names;
}

// The parts of `whole`, the asset of `file`, that the object is made of (MeshFile::only_parts,
// except_parts). Throws std::runtime_error starting with the path for a part name the file does
// not have (listing its parts) or a choice that leaves no triangle.
matgeom::ObjectAsset chosen_parts(const matgeom::ObjectAsset& whole, const MeshFile& file) {
  const bool only = !file.only_parts.empty();
  const std::vector<std::string>& names = only ? file.only_parts : file.except_parts;
  if (names.empty()) return whole;
  matgeom::NamedParts parts = matgeom::named_parts(whole.mesh, names);
  if (parts.missing)
    throw std::runtime_error(fmt::format("{}: {} \"{}\", but the file has no part of that name ({})", file.path,
                                         only ? "only_parts names" : "except_parts names", *parts.missing,
                                         quoted_part_names(whole.mesh)));
  if (!only) parts.named.flip();
  try {
    return matgeom::kept_parts(whole, parts.named);
  } catch (const std::invalid_argument&) {
    throw std::runtime_error(fmt::format("{}: {} leaves no part with a triangle ({})", file.path,
                                         only ? "only_parts" : "except_parts", quoted_part_names(whole.mesh)));
  }
}

// Mesh files read once per build, whatever the number of objects made from one (a scan's object
// and the room around it are two).
class MeshFileReads {
 public:
  const matgeom::ObjectAsset& whole(const MeshFile& file) {
    const auto key = std::make_pair(file.path, file.read_options.auto_smooth_deg);
    auto found = read_.find(key);
    if (found == read_.end()) found = read_.emplace(key, matgeom::read_object(file.path, file.read_options)).first;
    return found->second;
  }

 private:
  std::map<std::pair<std::string, std::optional<double>>, matgeom::ObjectAsset> read_;
};

matgeom::ObjectAsset read_source(const ObjectDescription& object, MeshFileReads& reads) {
  if (const auto* file = std::get_if<MeshFile>(&object.source)) {
    try {
      return chosen_parts(reads.whole(*file), *file);
    } catch (const std::exception& e) {
      throw object.origin.error("/mesh", e.what());
    }
  }
  if (const auto* given = std::get_if<GivenObject>(&object.source)) return *given->asset;
  if (const auto* room = std::get_if<RoomObject>(&object.source)) {
    try {
      return matgeom::ObjectAsset{matgeom::room_mesh(room->spec), {}, {}, {}};
    } catch (const std::invalid_argument& e) {
      throw object.origin.error("/room", e.what());
    }
  }
  const auto& builtin = std::get<BuiltinObject>(object.source);
  try {
    return matgeom::make_builtin_object(builtin.name, builtin.seed);
  } catch (const std::exception& e) {
    throw object.origin.error("/builtin", e.what());
  }
}

// Any failure to read a user's mesh is a problem with that input, whatever the library throws.
matgeom::ObjectAsset load_object(const ObjectDescription& object, MeshFileReads& reads) {
  matgeom::ObjectAsset asset = read_source(object, reads);
  const bool needs_uvs = object.uv_pass == UvPassMode::Always ||
                         (object.uv_pass == UvPassMode::WhenMissing && asset.mesh.uvs.empty());
  if (object.uv_scale != 1.0 && !needs_uvs)
    throw object.origin.error("/uv_scale",
                              "the UV pass does not run on this object (it has texture coordinates of its own, or "
                              "uv_pass is never), so there is no texel density to scale; use uv_pass \"always\"");
  if (needs_uvs) {
    try {
      matgeom::UvPassOptions options;
      options.texel_density_scale = object.uv_scale;
      asset.mesh = matgeom::uv_pass(asset.mesh, options).mesh;
    } catch (const std::exception& e) {
      throw object.origin.error("/uv_pass", e.what());
    }
  }
  return asset;
}

// The objects that are not surroundings as one surface, so that the rig is sized and the grid
// camera centred for every subject in the scene rather than for one object.
matgeom::TriangleMesh merged_surface(const std::vector<matgeom::ObjectAsset>& assets,
                                     const std::vector<ObjectDescription>& objects) {
  matgeom::TriangleMesh merged;
  for (size_t k = 0; k < assets.size(); ++k) {
    if (objects[k].surroundings) continue;
    const matgeom::ObjectAsset& asset = assets[k];
    const auto offset = static_cast<uint32_t>(merged.positions.size());
    merged.positions.insert(merged.positions.end(), asset.mesh.positions.begin(), asset.mesh.positions.end());
    for (const glm::uvec3& triangle : asset.mesh.triangles) merged.triangles.push_back(triangle + offset);
  }
  return merged;
}

size_t part_count(const matgeom::ObjectAsset& asset) {
  return std::max({static_cast<size_t>(asset.mesh.part_count()), asset.materials.size(), size_t{1}});
}

// The scene material of each of the `parts` parts of `mesh` the description assigns one to;
// parts left out keep the object's own material.
// `uv_scale` is the scale the object's UV pass ran at (SceneMaterials::id_on_part).
std::vector<std::optional<uint32_t>> assigned_materials(const ObjectDescription& object, const matgeom::TriangleMesh& mesh,
                                                        size_t parts, double uv_scale, SceneMaterials& materials,
                                                        Scene& scene) {
  std::vector<std::optional<uint32_t>> assigned(parts);
  if (object.material)
    for (size_t k = 0; k < assigned.size(); ++k)
      assigned[k] = materials.id_on_part(scene, *object.material, mesh, static_cast<uint32_t>(k), uv_scale);
  const std::vector<std::string>& names = mesh.part_names;
  for (const auto& [part, material] : object.part_materials) {
    bool found = false;
    for (size_t k = 0; k < assigned.size() && k < names.size(); ++k) {
      if (names[k] != part) continue;
      assigned[k] = materials.id_on_part(scene, material, mesh, static_cast<uint32_t>(k), uv_scale);
      found = true;
    }
    if (!found)
      throw object.origin.error(
          "/materials", fmt::format("the object has no part named \"{}\" ({})", part, quoted_part_names(mesh)));
  }
  return assigned;
}

void add_object(Scene& scene, const ObjectDescription& object, const matgeom::ObjectAsset& asset,
                SceneMaterials& materials) {
  const std::vector<std::optional<uint32_t>> assigned =
      assigned_materials(object, asset.mesh, part_count(asset), object.uv_scale, materials, scene);
  // A mesh or slot the renderer rejects (non-finite vertex, bad image index) is a bad input file.
  try {
    MeshOptions options;
    options.shadow_terminator_geometry_offset = object.shadow_terminator_geometry_offset;
    add_asset(scene, asset, assigned, options);
  } catch (const std::invalid_argument& e) {
    // Named by its file: the scene's own mesh numbering means nothing to whoever wrote the input.
    const auto* file = std::get_if<MeshFile>(&object.source);
    throw object.origin.error("", file ? file->path + ": " + e.what() : e.what());
  }
}

// The lamps, listed or the paper's rig around the objects (whose lamps an object too large for
// the scene limit would put beyond it).
void add_lights(const LightsDescription& lights, BuiltScene& built) {
  const auto* listed = std::get_if<std::vector<Lamp>>(&lights);
  try {
    if (listed) {
      for (const Lamp& light : *listed) built.scene.add_lamp(light);
      return;
    }
    built.rig = paper_rig(built.bounds, std::get<LightRigDescription>(lights).target_illuminance_lux);
    add_rig(built.scene, *built.rig);
  } catch (const std::invalid_argument& e) {
    throw matbase::InputError(std::string(listed ? "lights: " : "light rig: ") + e.what());
  }
}

// The object's mesh in world space, refused when the transform flattens it or moves it beyond
// what single precision resolves.
void place_object(const ObjectDescription& object, matgeom::TriangleMesh& mesh) {
  // Checked in double precision first: a huge scale would overflow the float positions.
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    const glm::dvec3 world(object.object_to_world * glm::dvec4(glm::dvec3(mesh.positions[v]), 1.0));
    if (!within_scene_limit(world))
      throw object.origin.error("", *scene_point_problem(world, "after its transform, vertex " + std::to_string(v)));
  }
  try {
    matgeom::transform_mesh(mesh, object.object_to_world);
  } catch (const std::invalid_argument&) {
    throw object.origin.error("", "the transform flattens the object onto a plane, a line or a point (a zero scale?)");
  }
}

glm::dmat4 camera_to_world(const CameraDescription& camera, const glm::dvec3& centroid) {
  if (const auto* look = std::get_if<LookAtPlacement>(&camera.placement)) {
    try {
      return matgeom::look_at_camera_to_world(look->position, look->target, look->up);
    } catch (const std::invalid_argument& e) {
      throw matbase::InputError(std::string("camera: ") + e.what());
    }
  }
  if (const auto* matrix = std::get_if<MatrixPlacement>(&camera.placement)) return matrix->camera_to_world;
  const auto& grid = std::get<GridPlacement>(camera.placement);
  matgeom::CameraGridSpec spec = grid.spec;
  if (grid.center_on_centroid) spec.center = centroid;
  try {
    return matgeom::grid_camera(spec, grid.i, grid.j).camera_to_world;
  } catch (const std::logic_error& e) {
    throw matbase::InputError(std::string("camera grid: ") + e.what());
  }
}

std::string frame_stem(const CameraDescription& camera) {
  const auto* grid = std::get_if<GridPlacement>(&camera.placement);
  return grid ? view_name(grid->i, grid->j) : "view";
}

// The world of `description`; a sky's sun is added to the lamps (matrender/sky.h).
void add_world(const BackgroundDescription& description, BuiltScene& built, EnvironmentImages* images = nullptr) {
  if (const auto* sky = std::get_if<SkyDescription>(&description)) {
    try {
      const SkyLighting lighting = sky_lighting(sky->sky);
      built.scene.set_background(lighting.map);
      if (lighting.sun) built.scene.add_lamp(*lighting.sun);
    } catch (const std::invalid_argument& e) {
      throw sky->origin.error("/sky", e.what());
    }
    return;
  }
  const auto* environment = std::get_if<EnvironmentDescription>(&description);
  if (!environment) {
    built.scene.set_background(std::get<glm::vec3>(description));
    return;
  }
  try {
    const ColorSpace space = environment->color_space ? *environment->color_space
                                                      : blender_default_color_space(environment->path);
    const std::string key = environment->path + (space == ColorSpace::SRGB ? " (sRGB)" : "");
    TexturePtr image = images && images->count(key) ? images->at(key) : Texture::load_radiance(environment->path, space);
    if (images) images->emplace(key, image);
    built.scene.set_background(EnvironmentMap{image, environment->strength, environment->rotation_z});
  } catch (const std::exception& e) {
    throw environment->origin.error("/environment", e.what());
  }
}

}  // namespace

void set_scene_lighting(BuiltScene& built, const LightsDescription& lights, const BackgroundDescription& background,
                        EnvironmentImages* images) {
  built.scene.clear_lamps();
  built.rig.reset();
  add_lights(lights, built);
  add_world(background, built, images);
}

BuiltScene build_scene(const SceneDescription& description, const std::atomic<bool>* cancel) {
  std::vector<matgeom::ObjectAsset> assets;
  MeshFileReads reads;
  for (const ObjectDescription& object : description.objects) {
    assets.push_back(load_object(object, reads));
    place_object(object, assets.back().mesh);
  }
  const matgeom::TriangleMesh surface = merged_surface(assets, description.objects);
  if (surface.positions.empty() && !description.objects.empty())
    throw description.objects.front().origin.error(
        "/surroundings", "every object of the scene is surroundings: name at least one the cameras and lamps are about");

  BuiltScene built;
  built.bounds = matgeom::minimal_enclosing_sphere(surface.positions);
  built.materials = SceneMaterials(description.materials);
  built.materials.cancel_on(cancel);
  for (size_t k = 0; k < assets.size(); ++k) {
    if (const auto* file = std::get_if<MeshFile>(&description.objects[k].source))
      for (const std::string& note : assets[k].notes) matgeom::add_note(built.notes, file->path + ": " + note);
    add_object(built.scene, description.objects[k], assets[k], built.materials);
    built.object_meshes.push_back(static_cast<uint32_t>(built.scene.mesh_count() - 1));
    built.object_uv_scales.push_back(description.objects[k].uv_scale);
    built.object_surfaces.push_back(std::move(assets[k].mesh));
  }
  add_lights(description.lights, built);
  add_world(description.background, built);
  built.centroid = matgeom::surface_centroid(surface);
  built.camera = scene_camera(description.camera, built);
  built.frame_stem = frame_stem(description.camera);
  built.scene.commit();
  return built;
}

matgeom::TriangleMesh placed_object_surface(const ObjectDescription& object) {
  MeshFileReads reads;
  matgeom::TriangleMesh mesh = read_source(object, reads).mesh;
  place_object(object, mesh);
  return mesh;
}

Camera scene_camera(const CameraDescription& description, const BuiltScene& built) {
  Camera camera;
  camera.camera_to_world = camera_to_world(description, built.centroid);
  camera.vertical_fov = description.vertical_fov;
  camera.width = description.width;
  camera.height = description.height;
  if (const std::optional<std::string> problem = scene_point_problem(glm::dvec3(camera.camera_to_world[3]), "the camera"))
    throw matbase::InputError("camera: " + *problem);
  return camera;
}

void assign_object_materials(BuiltScene& built, size_t object, const ObjectDescription& materials) {
  const uint32_t mesh = built.object_meshes.at(object);
  std::vector<uint32_t> ids = built.scene.part_materials(mesh);
  const std::vector<std::optional<uint32_t>> assigned =
      assigned_materials(materials, built.object_surfaces[object], ids.size(), built.object_uv_scales.at(object),
                         built.materials, built.scene);
  for (size_t k = 0; k < ids.size(); ++k)
    if (assigned[k]) ids[k] = *assigned[k];
  built.scene.set_part_materials(mesh, ids);
}

}  // namespace matrender
