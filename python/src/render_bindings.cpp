#include "render_bindings.h"

#include <atomic>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <fmt/format.h>
#include <pybind11/stl.h>

#include "camera_bindings.h"
#include "frame_arrays.h"
#include "json_text.h"
#include "loaded_scene.h"
#include "matbase/input_error.h"
#include "mesh_arrays.h"
#include "matrender/render.h"
#include "matrender/scene_builder.h"
#include "matrender/scene_file.h"
#include "releasing_gil.h"

namespace matpredict_python {
namespace {

namespace py = pybind11;

// Where a scene dict's errors point: "the scene: /render/spp: ...".
constexpr const char* kSceneSource = "the scene";

// The scene dict as JSON for the scene reader: an object whose "mesh" is a matpredict.Mesh gets
// {"given": K} in its place, K its index in `given`, where its arrays' object goes.
std::string scene_json(const py::dict& scene, std::vector<matrender::GivenObject>& given) {
  py::dict readable(scene);
  if (scene.contains("objects") && py::isinstance<py::list>(scene["objects"])) {
    py::list objects;
    for (const py::handle object : scene["objects"].cast<py::list>()) {
      if (py::isinstance<py::dict>(object) && object.cast<py::dict>().contains("mesh") &&
          py::isinstance<MeshArrays>(object.cast<py::dict>()["mesh"])) {
        py::dict reference(object.cast<py::dict>());
        py::dict mesh;
        mesh["given"] = given.size();
        given.push_back(matrender::GivenObject{reference["mesh"].cast<MeshArrays>().asset});
        reference["mesh"] = mesh;
        objects.append(reference);
      } else {
        objects.append(object);
      }
    }
    readable["objects"] = objects;
  }
  return json_text(readable, matbase::DocumentSource(kSceneSource, matbase::PathStyle::JsonPointer));
}

// A scene file's path, or a dict with its keys (relative paths from the current folder).
std::unique_ptr<LoadedScene> load_scene(const py::object& scene_or_path) {
  auto scene = std::make_unique<LoadedScene>();
  if (py::isinstance<py::dict>(scene_or_path)) {
    std::vector<matrender::GivenObject> given;
    const std::string json = scene_json(scene_or_path.cast<py::dict>(), given);
    scene->description = matrender::read_scene_text(json, kSceneSource, std::filesystem::current_path().string(), given);
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

// Sets the declared setting `name` to an argument, refused in the declaration's words.
void assign_argument(matrender::RenderSettings& settings, std::string_view name, int64_t value) {
  const matrender::RenderSettingDeclaration& setting = matrender::render_setting(name);
  if (const std::optional<std::string> problem = matrender::number_problem(setting, static_cast<double>(value)))
    throw py::value_error(std::string(name) + ": " + *problem);
  matrender::assign_number(settings, setting, static_cast<double>(value));
}

py::dict render(LoadedScene& scene, const py::object& camera_choice, std::optional<int64_t> spp, std::optional<int64_t> seed,
                int64_t threads, const std::optional<std::variant<std::string, std::vector<std::string>>>& aovs,
                const py::object& progress) {
  const matrender::Camera camera = chosen_camera(scene, camera_choice);
  matrender::RenderSettings settings = scene.description.settings;
  if (spp) assign_argument(settings, "spp", *spp);
  if (seed) assign_argument(settings, "seed", *seed);
  assign_argument(settings, "threads", threads);
  settings.aovs = aov_mask(aovs, settings.aovs);
  if (!progress.is_none() && !PyCallable_Check(progress.ptr()))
    throw py::type_error("progress: expected None or a callable taking the finished fraction");
  std::atomic<bool> cancel{false};
  std::atomic<double> fraction{0.0};
  settings.cancel = &cancel;
  settings.progress = [&fraction](double f) { fraction.store(f); };
  matrender::FrameBuffers frame;
  double reported = -1.0;
  run_releasing_gil([&] { matrender::render(scene.built.scene, camera, settings, frame); }, cancel, [&] {
    if (const double f = fraction.load(); !progress.is_none() && f != reported) {
      reported = f;
      progress(f);
    }
  });
  return frame_arrays(std::move(frame));
}

// Every array render() can return, with the frame's layout of it.
struct ArrayInfo {
  std::string name;
  std::string dtype;
  int channels;
  bool is_default;
  std::string description;
};

std::vector<ArrayInfo> array_infos() {
  matrender::FrameBuffers layout;  // empty: only which buffer, its element type and channels are asked
  const auto info = [&layout](const std::string& name, uint32_t bit, bool is_default, const std::string& description) {
    const matrender::FrameBufferView view = matrender::frame_buffer(layout, bit);
    return ArrayInfo{name, view.ints ? "int32" : "float32", view.channels, is_default, description};
  };
  std::vector<ArrayInfo> infos{info("color", 0, true, matrender::kColorDescription)};
  for (const matrender::AovName& aov : matrender::aov_names())
    infos.push_back(info(aov.name, aov.bit, (aov.bit & matrender::default_aovs()) != 0, aov.description));
  return infos;
}

py::dict aov_info() {
  py::dict table;
  for (const ArrayInfo& array : array_infos()) {
    py::dict entry;
    entry["dtype"] = array.dtype;
    entry["channels"] = array.channels;
    entry["default"] = array.is_default;
    entry["description"] = array.description;
    table[array.name.c_str()] = entry;
  }
  return table;
}

// "  roughness  float32 x 1  (default)  the material's roughness ..." one array a line.
std::string aov_table_text() {
  std::string text;
  for (const ArrayInfo& array : array_infos())
    text += fmt::format("  {:<22} {} x {}{}: {}\n", array.name, array.dtype, array.channels,
                        array.is_default ? ", default" : "", array.description);
  return text;
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
      .def_property_readonly("bounds", [](const LoadedScene& s) {
        const matgeom::Sphere& sphere = s.built.bounds;
        return py::make_tuple(py::make_tuple(sphere.center.x, sphere.center.y, sphere.center.z), sphere.radius);
      }, "((x, y, z), radius): the smallest sphere around all objects, metres, world frame.")
      .def_property_readonly("notes", [](const LoadedScene& s) { return s.built.notes; },
                             "What the scene's mesh files hold that their readers do not apply, or apply otherwise\n"
                             "than Blender 3.4 (a glTF extension, a material's texture): a list of '<file>: <note>'.")
      .def_property_readonly("camera", [](const LoadedScene& s) { return s.built.camera; },
                             "The scene file's camera, a matpredict.Camera.")
      .def("make_camera", &camera_from_dict, py::arg("description"),
           "The camera a dict with a scene file camera's keys places in this scene (docs/scene_format.md,\n"
           "'Camera': 'position' and 'look_at', 'grid' (centred on the objects unless it gives 'center')\n"
           "or 'matrix'; 'fov_deg', 'width', 'height'). Raises matpredict.InputError naming the key.")
      .def("grid_cameras", &grid_cameras, py::arg("grid") = py::none(),
           "Every camera of a latitude-longitude grid around this scene's objects, {view name: Camera}\n"
           "row by row ('view_000_000', 'view_000_001', ...), with the scene camera's size and field of\n"
           "view: `grid` takes a scene file grid's keys but 'cell' (n_phi, n_theta, radius,\n"
           "phi_range_deg, theta_range_deg, center); None is the paper's 16 x 32 grid of 1 m.")
      .def("__repr__", [](const LoadedScene& s) {
        return "<matpredict.Scene " + std::to_string(s.built.camera.width) + "x" + std::to_string(s.built.camera.height) + ">";
      });

  module.def("load_scene", &load_scene, py::arg("scene"),
             "Reads a JSON scene file (docs/scene_format.md), or a dict with the same keys (relative paths\n"
             "from the current folder), and builds it: meshes, textures and materials loaded, the BVH built.\n"
             "Raises matpredict.InputError naming the file (or 'the scene'), the JSON pointer and the problem.");
  static const std::string render_doc =
      "Renders the scene and returns a dict of numpy arrays, each (height, width, channels), C-contiguous,\n"
      "row 0 at the top, sharing the frame's memory (no copy): 'color' and the AOVs asked for: None or\n"
      "'default' (the default ones), 'all', or a list of names.\n"
      "`camera` is None (the scene's), a matpredict.Camera or a dict with a scene file camera's keys:\n"
      "one built scene renders from any number of cameras. spp and seed override the scene file's; the\n"
      "image is the same for a seed whatever `threads` (0: all cores). The GIL is released while\n"
      "rendering; `progress` is called on this thread with the finished fraction; Ctrl-C stops the render\n"
      "with KeyboardInterrupt.\n\nThe arrays (matpredict.aov_info() gives the same as a dict):\n" +
      aov_table_text();
  module.def("render", &render, py::arg("scene"), py::kw_only(), py::arg("camera") = py::none(), py::arg("spp") = py::none(),
             py::arg("seed") = py::none(), py::arg("threads") = 0, py::arg("aovs") = py::none(),
             py::arg("progress") = py::none(), render_doc.c_str());
  module.def("aov_names", [] {
    std::vector<std::string> names;
    for (const matrender::AovName& aov : matrender::aov_names()) names.push_back(aov.name);
    return names;
  }, "Every AOV's name, in the order render() returns them.");
  module.def("aov_info", &aov_info,
             "{name: {'dtype', 'channels', 'default', 'description'}} for 'color' and every AOV, in the order\n"
             "render() returns them: what each array holds (units, colour space or frame, the background's value).");
}

}  // namespace matpredict_python
