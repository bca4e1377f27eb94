#include "default_scene.h"

#include <algorithm>
#include <charconv>

#include "matgeom/builtin_objects.h"

namespace render_object {
namespace {

ObjectDescription object_from(std::variant<MeshFile, BuiltinObject> source, std::string option) {
  ObjectDescription object;
  object.source = std::move(source);
  object.origin = Origin{std::move(option), std::nullopt};
  return object;
}

std::string joined(const std::vector<std::string>& names) {
  std::string list;
  for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
  return list;
}

uint32_t parse_seed(const std::string& text) {
  uint32_t seed = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, seed);
  if (text.empty() || error != std::errc() || stop != end)
    throw InputError("--object: seed \"" + text + "\" is not an integer in [0, 4294967295]");
  return seed;
}

}  // namespace

GridPlacement paper_grid_placement() {
  GridPlacement grid;  // matgeom::CameraGridSpec's defaults are the paper's grid
  grid.center_on_centroid = true;
  grid.i = 5;
  grid.j = 16;
  return grid;
}

SceneDescription object_scene(ObjectDescription object) {
  SceneDescription scene;
  scene.camera.placement = paper_grid_placement();
  // The paper's power formula gives about 1e5-1e6 lx at the centre although the paper aims for
  // about 1 klx; objects rendered without a scene file are normalised to that stated aim
  // (--paper-powers keeps the formula's powers).
  LightRigDescription rig;
  rig.target_illuminance_lux = kPaperTargetIlluminanceLux;
  scene.lights = rig;
  scene.objects.push_back(std::move(object));
  return scene;
}

SceneDescription default_scene() {
  ObjectDescription vase = object_from(BuiltinObject{"vase", 0}, "the default scene");
  return object_scene(std::move(vase));
}

ObjectDescription mesh_file_object(const std::string& path) { return object_from(MeshFile{path}, "--mesh"); }

ObjectDescription builtin_object(const std::string& argument) {
  const size_t colon = argument.find(':');
  BuiltinObject builtin{argument.substr(0, colon), 0};
  const std::vector<std::string> names = matgeom::builtin_object_names();
  if (std::find(names.begin(), names.end(), builtin.name) == names.end())
    throw InputError("--object: unknown built-in object \"" + builtin.name + "\" (available: " + joined(names) + ")");
  if (colon != std::string::npos) builtin.seed = parse_seed(argument.substr(colon + 1));
  return object_from(builtin, "--object");
}

}  // namespace render_object
