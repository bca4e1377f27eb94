#include "render_bindings.h"

#include <atomic>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <pybind11/stl.h>

#include "frame_arrays.h"
#include "json_text.h"
#include "matbase/input_error.h"
#include "matgeom/builtin/builtin_objects.h"
#include "mesh_arrays.h"
#include "matrender/render.h"
#include "matrender/scene_builder.h"
#include "matrender/scene_file.h"
#include "releasing_gil.h"

namespace matpredict_python {
namespace {

namespace py = pybind11;

// A scene as described and as built, ready to render any number of times.
struct LoadedScene {
  matrender::SceneDescription description;
  matrender::BuiltScene built;
};

// Where a scene dict's errors point: "the scene: /render/spp: ...".
constexpr const char* kSceneSource = "the scene";

// The keys of a scene file's mesh object (docs/scene_format.md, "Objects").
const char* const kMeshObjectKeys =
    "\"mesh\", \"transform\", \"material\", \"materials\", \"shadow_terminator_geometry_offset\"";

// The scene dict as JSON for the file's reader. An object whose "mesh" is a matpredict.Mesh is
// read with a built-in object in its place (its other keys as a mesh object's) and given the
// arrays' mesh after; `given` collects them by object index.
std::string scene_json(const py::dict& scene, std::vector<std::pair<size_t, MeshArrays>>& given) {
  py::dict readable(scene);
  if (scene.contains("objects") && py::isinstance<py::list>(scene["objects"])) {
    py::list objects;
    size_t index = 0;
    for (const py::handle object : scene["objects"].cast<py::list>()) {
      const std::string place = std::string(kSceneSource) + ": /objects/" + std::to_string(index);
      if (py::isinstance<py::dict>(object) && object.cast<py::dict>().contains("mesh") &&
          py::isinstance<MeshArrays>(object.cast<py::dict>()["mesh"])) {
        py::dict stand_in(object.cast<py::dict>());
        if (stand_in.contains("builtin")) throw matbase::InputError(place + ": expected exactly one of \"mesh\" or \"builtin\"");
        if (stand_in.contains("seed"))
          throw matbase::InputError(place + "/seed: unknown key (allowed here: " + kMeshObjectKeys + ")");
        given.emplace_back(index, stand_in["mesh"].cast<MeshArrays>());
        PyDict_DelItemString(stand_in.ptr(), "mesh");
        stand_in["builtin"] = matgeom::builtin_object_names().front();
        objects.append(stand_in);
      } else {
        objects.append(object);
      }
      ++index;
    }
    readable["objects"] = objects;
  }
  return json_text(readable);
}

// A scene file's path, or a dict with its keys (relative paths from the current folder).
std::unique_ptr<LoadedScene> load_scene(const py::object& scene_or_path) {
  auto scene = std::make_unique<LoadedScene>();
  if (py::isinstance<py::dict>(scene_or_path)) {
    std::vector<std::pair<size_t, MeshArrays>> given;
    const std::string json = scene_json(scene_or_path.cast<py::dict>(), given);
    scene->description = matrender::read_scene_text(json, kSceneSource, std::filesystem::current_path().string());
    for (const auto& [index, mesh] : given) scene->description.objects[index].source = matrender::GivenObject{mesh.asset};
  } else {
    scene->description = matrender::read_scene_file(py::str(py::module_::import("os").attr("fspath")(scene_or_path)));
  }
  py::gil_scoped_release release;  // loading meshes and textures needs no Python
  scene->built = matrender::build_scene(scene->description);
  return scene;
}

std::string known_aovs() {
  std::string names;
  for (const matrender::AovName& aov : matrender::aov_names()) names += (names.empty() ? "" : ", ") + aov.name;
  return names;
}

// None: the scene settings' AOVs (the default ones); "all", "default", or a list of names.
uint32_t aov_mask(const std::optional<std::variant<std::string, std::vector<std::string>>>& aovs, uint32_t scene_aovs) {
  if (!aovs) return scene_aovs;
  if (const auto* word = std::get_if<std::string>(&*aovs)) {
    if (*word == "all") return matrender::all_aovs();
    if (*word == "default") return matrender::default_aovs();
    throw py::value_error("aovs: expected \"all\", \"default\" or a list of AOV names, got \"" + *word + "\"");
  }
  uint32_t mask = 0;
  for (const std::string& name : std::get<std::vector<std::string>>(*aovs)) {
    const std::optional<uint32_t> bit = matrender::aov_named(name);
    if (!bit) throw py::value_error("aovs: unknown AOV \"" + name + "\" (known: " + known_aovs() + ")");
    mask |= *bit;
  }
  return mask;
}

py::dict render(LoadedScene& scene, std::optional<int> spp, std::optional<uint32_t> seed, int threads,
                const std::optional<std::variant<std::string, std::vector<std::string>>>& aovs, const py::object& progress) {
  matrender::RenderSettings settings = scene.description.settings;
  if (spp) {
    if (*spp < 1) throw py::value_error("spp: expected a whole number of at least 1, got " + std::to_string(*spp));
    settings.samples_per_pixel = *spp;
  }
  if (seed) settings.seed = *seed;
  if (threads < 0) throw py::value_error("threads: expected 0 (all) or more, got " + std::to_string(threads));
  settings.threads = threads;
  settings.aovs = aov_mask(aovs, settings.aovs);
  if (!progress.is_none() && !PyCallable_Check(progress.ptr()))
    throw py::type_error("progress: expected None or a callable taking the finished fraction");
  std::atomic<bool> cancel{false};
  std::atomic<double> fraction{0.0};
  settings.cancel = &cancel;
  settings.progress = [&fraction](double f) { fraction.store(f); };
  matrender::FrameBuffers frame;
  double reported = -1.0;
  run_releasing_gil([&] { matrender::render(scene.built.scene, scene.built.camera, settings, frame); }, cancel, [&] {
    if (const double f = fraction.load(); !progress.is_none() && f != reported) {
      reported = f;
      progress(f);
    }
  });
  return frame_arrays(std::move(frame));
}

}  // namespace

void bind_render(py::module_& module) {
  py::class_<LoadedScene>(module, "Scene", "A scene loaded and built, ready to render (matpredict.load_scene).")
      .def_property_readonly("width", [](const LoadedScene& s) { return s.built.camera.width; }, "Image width in pixels.")
      .def_property_readonly("height", [](const LoadedScene& s) { return s.built.camera.height; }, "Image height in pixels.")
      .def_property_readonly("spp", [](const LoadedScene& s) { return s.description.settings.samples_per_pixel; },
                             "Samples per pixel the scene file asks for.")
      .def_property_readonly("seed", [](const LoadedScene& s) { return s.description.settings.seed; },
                             "The sampler's seed the scene file gives.")
      .def_property_readonly("exposure_stops", [](const LoadedScene& s) { return s.description.exposure_stops; },
                             "Stops the scene file applies to its display images (not to the arrays).")
      .def("__repr__", [](const LoadedScene& s) {
        return "<matpredict.Scene " + std::to_string(s.built.camera.width) + "x" + std::to_string(s.built.camera.height) + ">";
      });

  module.def("load_scene", &load_scene, py::arg("scene"),
             "Reads a JSON scene file (docs/scene_format.md), or a dict with the same keys (relative paths\n"
             "from the current folder), and builds it: meshes, textures and materials loaded, the BVH built.\n"
             "Raises matpredict.InputError naming the file (or 'the scene'), the JSON pointer and the problem.");
  module.def("render", &render, py::arg("scene"), py::kw_only(), py::arg("spp") = py::none(),
             py::arg("seed") = py::none(), py::arg("threads") = 0, py::arg("aovs") = py::none(),
             py::arg("progress") = py::none(),
             "Renders the scene's camera view and returns a dict of numpy arrays, each (height, width,\n"
             "channels) with row 0 at the top: 'color' (float32 RGB, scene-linear Rec.709, no exposure\n"
             "applied) and every AOV asked for (None or 'default': the default ones; 'all'; or a list\n"
             "of names, matpredict.aov_names()): material parameters (colours linear RGB, scalars one channel),\n"
             "normal_world and normal_camera (XYZ in [-1, 1]; camera: +X right, +Y up, +Z toward the\n"
             "viewer), normal_tangent, depth (metres along the camera axis), alpha (coverage),\n"
             "ambient_occlusion, color_variance (float32), label, part_id and sample_count (int32).\n"
             "spp and seed override the scene file's; the image is the same for a seed whatever\n"
             "`threads` (0: all cores). The GIL is released while rendering; `progress` is called on\n"
             "this thread with the finished fraction; Ctrl-C stops the render with KeyboardInterrupt.");
  module.def("aov_names", [] {
    std::vector<std::string> names;
    for (const matrender::AovName& aov : matrender::aov_names()) names.push_back(aov.name);
    return names;
  }, "Every AOV's name, in the order render() returns them.");
}

}  // namespace matpredict_python
