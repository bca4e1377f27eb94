#include "options.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "common/number_options.h"
#include "common/thread_count.h"
#include "matbase/number_text.h"
#include "matgeom/builtin/builtin_objects.h"
#include "matgeom/shading_normals.h"
#include "matrender/builtin_environments.h"
#include "matrender/denoiser.h"
#include "matrender/camera.h"
#include "matrender/image_io.h"
#include "matrender/paper_setup.h"
#include "matrender/render.h"
#include "matdataset/maker/frame_scene.h"
#include "matdataset/maker/object_renderer.h"
#include "matrender/scene_file.h"
#include "matrender/scene_overrides.h"

namespace render_object {
namespace {

using matrender::BuiltinObject;
using matrender::GridPlacement;
using matbase::InputError;
using matrender::LookAtPlacement;
using matrender::MeshFile;
using matrender::ObjectDescription;
using matrender::Origin;
using matrender::SceneDescription;

// The largest grid side the options take; a larger grid has cells finer than any dataset samples.
constexpr int kMaxGridSize = 65536;

// Thrown from an option callback, CLI11 reports it like its own errors ("--spp: expected ...").
void require(bool ok, const std::string& option, const std::string& expectation) {
  if (!ok) throw CLI::ValidationError(option, "expected " + expectation);
}

// --sky default, or --sky sun_elevation_deg=30,air=2,sun_disc=false,strength=0.5: the scene
// file's sky keys (matrender::sky_settings) with their ranges.
matrender::NishitaSky parse_sky(const std::string& text) {
  matrender::NishitaSky sky;
  if (text == "default") return sky;
  for (const std::string& item : CLI::detail::split(text, ',')) {
    const size_t equals = item.find('=');
    if (equals == std::string::npos)
      throw CLI::ValidationError("--sky", "\"" + item + "\" is not KEY=VALUE (or give \"default\")");
    const std::string key = item.substr(0, equals), value = item.substr(equals + 1);
    if (key == "sun_disc") {
      if (value != "true" && value != "false") throw CLI::ValidationError("--sky", "sun_disc is true or false");
      sky.sun_disc = value == "true";
      continue;
    }
    const std::optional<double> number = matbase::finite_number(value);
    if (!number) throw CLI::ValidationError("--sky", key + ": \"" + value + "\" is not a finite number");
    const auto& settings = matrender::sky_settings();
    const auto setting = std::find_if(settings.begin(), settings.end(), [&](const auto& s) { return s.key == key; });
    if (key == "strength")
      sky.strength = *number;
    else if (setting != settings.end())
      sky.*(setting->field) = *number * setting->unit;
    else
      throw CLI::ValidationError("--sky", "unknown key \"" + key + "\"");
  }
  if (const std::optional<std::string> problem = matrender::sky_problem(sky)) throw CLI::ValidationError("--sky", *problem);
  return sky;
}

uint32_t parse_aov_list(const std::string& text) {
  if (text == "default") return matrender::default_aovs();
  if (text == "all") return matrender::all_aovs();
  if (text == "none") return 0;
  uint32_t mask = 0;
  for (const std::string& name : CLI::detail::split(text, ',')) {
    const std::optional<uint32_t> aov = matrender::aov_named(name);
    if (!aov) {
      std::string known = "default, all, none";
      for (const matrender::AovName& entry : matrender::aov_names()) known += ", " + entry.name;
      throw CLI::ValidationError("--aovs", "unknown AOV \"" + name + "\" (expected a comma-separated list of: " +
                                               known + ")");
    }
    mask |= *aov;
  }
  return mask;
}

// "passes written besides colour: default (base_color, ...), all, none, or a comma-separated list of ..."
std::string aov_help() {
  std::string defaults, names;
  for (const matrender::AovName& aov : matrender::aov_names()) {
    names += (names.empty() ? "" : ", ") + aov.name;
    if (aov.bit & matrender::default_aovs()) defaults += (defaults.empty() ? "" : ", ") + aov.name;
  }
  return "passes written besides colour: default (" + defaults + "), all, none, or a comma-separated list of " + names;
}

// An image side as the scene file takes it; the checked text converts.
CLI::Validator image_side() { return app_support::whole_number_in(1, matrender::kMaxImageSide); }

void set_resolution(const std::string& text, Options& options) {
  const size_t x = text.find_first_of("xX");
  require(x != std::string::npos, "--resolution", "WIDTHxHEIGHT, e.g. 512x512");
  const std::string width = text.substr(0, x), height = text.substr(x + 1);
  for (const std::string* side : {&width, &height})
    if (const std::optional<std::string> problem = matbase::whole_number_problem(*side, 1, matrender::kMaxImageSide))
      throw CLI::ValidationError("--resolution", "each side: " + *problem);
  options.width = std::stoi(width);
  options.height = std::stoi(height);
}

glm::dvec3 parse_point(const std::string& option, const std::string& text) {
  const std::vector<std::string> parts = CLI::detail::split(text, ',');
  glm::dvec3 point(0.0);
  bool ok = parts.size() == 3;
  for (int k = 0; ok && k < 3; ++k)
    ok = CLI::detail::lexical_cast(parts[static_cast<size_t>(k)], point[k]) && std::isfinite(point[k]);
  require(ok, option, "X,Y,Z (three finite numbers, metres)");
  return point;
}

// "a, b, c".
std::string joined(const std::vector<std::string>& names) {
  std::string list;
  for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
  return list;
}

// CLI::ExistingFile without its ":FILE" tag in --help, where the type name already says it.
CLI::Validator existing_file() {
  CLI::Validator validator = CLI::ExistingFile;
  validator.description("");
  return validator;
}

void add_scene_options(CLI::App& app, Options& o) {
  const std::string group = "Scene";
  auto* scene = app.add_option_function<std::string>(
                       "--scene", [&o](const std::string& path) { o.scene_file = path; },
                       "JSON scene file (docs/scene_format.md): camera, lights, background, objects, materials")
                    ->check(existing_file())
                    ->type_name("FILE.json")
                    ->group(group);
  auto* mesh = app.add_option_function<std::string>(
                      "--mesh", [&o](const std::string& path) { o.mesh_file = path; },
                      "render this .glb/.gltf/.ply/.obj object under the paper's light rig and grid camera")
                   ->check(existing_file())
                   ->type_name("FILE.glb|gltf|ply|obj")
                   ->group(group);
  auto* object = app.add_option_function<std::string>(
                        "--object", [&o](const std::string& name) { o.object = name; },
                        "render a built-in object (NAME or NAME:SEED) under the paper's rig and grid camera")
                     ->type_name("NAME[:SEED]")
                     ->group(group);
  auto* dataset_frame =
      app.add_option_function<std::string>(
             "--dataset-frame", [&o](const std::string& path) { o.dataset_frame = path; },
             "render one frame of a make_dataset dataset again from its records (its configuration in metadata.json, "
             "its camera, lighting and exposure in transforms.json), e.g. dataset_out/vase/var000/003: the colour "
             "PNG is the dataset's image")
          ->type_name("VARIANT/STEM")
          ->group(group);
  scene->excludes(mesh)->excludes(object)->excludes(dataset_frame);
  mesh->excludes(object)->excludes(dataset_frame);
  object->excludes(dataset_frame);
  app.add_option_function<double>(
         "--auto-smooth", [&o](const double& degrees) { o.auto_smooth_deg = degrees; },
         "shade the --mesh faces the file gives no normals smooth, except across edges sharper than DEG "
         "(Blender's Auto Smooth; for scans without normals). Without it they are flat, or as an OBJ's "
         "\"s\" statements say")
      ->check(app_support::number_in(0.0, matgeom::kMaxAutoSmoothDeg, /*low_open=*/true))
      ->type_name("DEG")
      ->needs(mesh)
      ->group(group);
  app.add_option_function<double>(
         "--uv-scale", [&o](const double& scale) { o.uv_scale = scale; },
         "give the --mesh or --object new texture coordinates from the paper's UV pass, at S times its texel "
         "density (the paper's user scale s: a material's maps repeat 1/S times as often)")
      ->check(app_support::number_in(matrender::kMinUvScale, matrender::kMaxUvScale, false))
      ->type_name("S")
      ->group(group);
  auto* library_material =
      app.add_option_function<std::string>(
             "--material",
             [&o](const std::string& text) {
               try {
                 o.material = matmaterial::parse_library_material(text);
               } catch (const std::invalid_argument& e) {
                 throw CLI::ValidationError("--material", e.what());
               }
             },
             "render every object in a material of the procedural library: a class, optionally one of its "
             "styles, and a seed (wood, wood:3, wood/wicker:3; --list-materials lists them)")
          ->type_name("CLASS[/STYLE][:SEED]")
          ->group(group);
  app.add_option("--material-resolution", o.material_resolution,
                 "texels along each side of the --material's maps (the scene file's \"resolution\")")
      ->check(CLI::Range(matmaterial::kMinLibraryResolution, matmaterial::kMaxLibraryResolution))
      ->default_val(o.material_resolution)
      ->type_name("N")
      ->group(group);
  auto* material_dir = app.add_option("--material-dir", o.material_dir,
                 "render every object in the material of this folder: MatSynth's layout (basecolor.png, "
                 "roughness.png, metallic.png, normal.png, opacity.png and an optional metadata.json; "
                 "docs/scene_format.md, \"Material folders\")")
      ->check(CLI::ExistingDirectory)
      ->type_name("FOLDER")
      ->group(group);
  library_material->excludes(material_dir);
  const CLI::Validator file = existing_file();
  app.add_option("--environment", o.environment,
                 "light the scene with this equirectangular (latitude-longitude) image, as Blender's World > "
                 "Environment Texture, or with one of the built-in ones (" + joined(matrender::builtin_environment_names()) +
                     ", from Debian's blender-data); camera rays that miss see it (replaces the scene's background)")
      ->check(CLI::Validator(
          [file](std::string& text) { return matrender::is_builtin_environment(text) ? std::string() : file(text); }, ""))
      ->type_name("FILE.exr|hdr|png|NAME")
      ->group(group);
  app.add_option_function<double>(
         "--environment-strength",
         [&o](const double& strength) {
           require(strength >= 0.0 && std::isfinite(strength), "--environment-strength", "a finite number >= 0");
           o.environment_strength = strength;
         },
         "the environment's strength (World > Background > Strength)")
      ->default_str("1")
      ->group(group);
  app.add_option_function<double>(
         "--environment-rotation",
         [&o](const double& degrees) {
           require(std::isfinite(degrees), "--environment-rotation", "a finite angle in degrees");
           o.environment_rotation_deg = degrees;
         },
         "turn the environment about +Z by this many degrees (a Mapping node's Rotation Z)")
      ->type_name("DEG")
      ->default_str("0")
      ->group(group);
  std::string sky_keys = "sun_disc, strength";
  for (const matrender::SkySetting& setting : matrender::sky_settings()) sky_keys += std::string(", ") + setting.key;
  app.add_option_function<std::string>(
         "--sky", [&o](const std::string& text) { o.sky = parse_sky(text); },
         "light the scene with a daylight sky and sun, Blender 3.4's Sky Texture (Nishita), in place of the "
         "background: \"default\" (the sun 15 degrees up towards +Y) or KEY=VALUE,... of " + sky_keys +
             " (docs/scene_format.md, \"Sky\"); daylight is bright: add --exposure auto")
      ->type_name("default|KEY=VALUE,...")
      ->excludes("--environment")
      ->group(group);
  app.add_flag("--list-objects", o.list_objects, "print the built-in object names and exit")->group(group);
  app.add_flag("--list-parameters", o.list_parameters,
               "print the material parameters scene files take (a markdown table) and exit")
      ->group(group);
  app.add_flag("--list-settings", o.list_settings,
               "print the render settings a scene file's \"render\" block takes, each also an option here (a "
               "markdown table) and exit")
      ->group(group);
  app.add_flag("--list-materials", o.list_materials,
               "print the material classes, their label ids and what each models, then the procedural library's "
               "styles and ranges (markdown tables) and exit")
      ->group(group);
}

void add_camera_options(CLI::App& app, Options& o) {
  const std::string group = "Camera (override the scene's)";
  const matrender::Camera camera;
  const GridPlacement grid = matrender::paper_grid_placement();
  auto* resolution = app.add_option_function<std::string>(
                            "--resolution", [&o](const std::string& text) { set_resolution(text, o); },
                            "image size in pixels")
                         ->type_name("WxH")
                         ->default_str(fmt::format("{}x{}", camera.width, camera.height))
                         ->group(group);
  auto* width = app.add_option_function<int>(
                       "--width", [&o](const int& w) { o.width = w; }, "image width in pixels")
                    ->check(image_side())
                    ->default_str(std::to_string(camera.width))
                    ->group(group);
  auto* height = app.add_option_function<int>(
                        "--height", [&o](const int& h) { o.height = h; }, "image height in pixels")
                     ->check(image_side())
                     ->default_str(std::to_string(camera.height))
                     ->group(group);
  resolution->excludes(width)->excludes(height);
  app.add_option_function<double>(
         "--fov-deg",
         [&o](const double& fov) {
           require(fov > 0.0 && fov < 180.0, "--fov-deg", "an angle in (0, 180) degrees");
           o.fov_deg = fov;
         },
         "vertical field of view in degrees (the default is Blender's 50 mm lens)")
      ->default_str(fmt::format("{:.4f}", glm::degrees(camera.vertical_fov)))
      ->group(group);
  // Cells beyond the grid are refused once the grid is known.
  auto* cell = app.add_option_function<std::array<int, 2>>(
                      "--cell", [&o](const std::array<int, 2>& c) { o.cell = c; },
                      "grid camera cell I,J (I: polar row from the zenith, J: azimuth column)")
                   ->check(app_support::whole_number_in(0, kMaxGridSize - 1))
                   ->delimiter(',')
                   ->type_name("I,J")
                   ->default_str(fmt::format("{},{}", grid.i, grid.j))
                   ->group(group);
  auto* grid_size = app.add_option_function<std::array<int, 2>>(
                           "--grid", [&o](const std::array<int, 2>& g) { o.grid = g; },
                           "camera grid size NPHI,NTHETA over polar [0, 90] and azimuth [-90, 90] degrees")
                        ->check(app_support::whole_number_in(1, kMaxGridSize))
                        ->delimiter(',')
                        ->type_name("NPHI,NTHETA")
                        ->default_str(fmt::format("{},{}", grid.spec.n_phi, grid.spec.n_theta))
                        ->group(group);
  auto* radius = app.add_option_function<double>(
                        "--radius",
                        [&o](const double& r) {
                          require(r > 0.0, "--radius", "a positive number");
                          o.radius = r;
                        },
                        "grid camera distance from the object's surface centroid, metres")
                     ->default_str(fmt::format("{}", grid.spec.radius))
                     ->group(group);
  auto* position = app.add_option_function<std::string>(
                          "--camera-position",
                          [&o](const std::string& p) { o.camera_position = parse_point("--camera-position", p); },
                          "explicit camera position (metres, +Z up); needs --look-at")
                       ->type_name("X,Y,Z")
                       ->group(group);
  auto* look_at = app.add_option_function<std::string>(
                         "--look-at", [&o](const std::string& p) { o.look_at = parse_point("--look-at", p); },
                         "point the explicit camera looks at")
                      ->type_name("X,Y,Z")
                      ->group(group);
  position->needs(look_at)->excludes(cell)->excludes(grid_size)->excludes(radius);
  look_at->needs(position);
}

// How render_object spells a declared setting: --NAME with hyphens, or an older spelling kept.
std::string option_spelling(const matrender::RenderSettingDeclaration& setting) {
  if (setting.name == "transparent_background") return "--transparent";
  std::string option = "--" + std::string(setting.name);
  std::replace(option.begin(), option.end(), '_', '-');
  return option;
}

// What --help shows an option's value as: INT, FLOAT, or the choices (importance|uniform).
std::string value_name(const matrender::RenderSettingDeclaration& setting) {
  if (setting.form == matrender::SettingForm::WholeNumber) return "INT";
  if (setting.form == matrender::SettingForm::Number) return "FLOAT";
  std::string choices;
  for (const std::string_view choice : setting.choices) choices += (choices.empty() ? "" : "|") + std::string(choice);
  return choices;
}

// An option taking a value of `setting`, checked against its declaration as it is read and then
// handed to `take` as text; --help shows its documentation, range and default.
template <class Take>
void add_setting_value_option(CLI::App& app, const matrender::RenderSettingDeclaration& setting, const std::string& option,
                              const std::string& group, Take take) {
  app.add_option_function<std::string>(
         option,
         [&setting, option, take](const std::string& text) {
           matrender::RenderSettings checked;
           if (const std::optional<std::string> problem = matrender::assign_text(checked, setting, text))
             throw CLI::ValidationError(option, *problem);
           take(text, checked);
         },
         std::string(setting.documentation) + " (" + matrender::expectation(setting) + ")")
      ->type_name(value_name(setting))
      ->default_str(matrender::default_text(setting))
      ->group(group);
}

// One option per declared setting of `scope`: a switch is a flag that turns it from its default
// (--no-NAME where it is on), any other setting takes a value its declaration checks.
void add_setting_options(CLI::App& app, Options& o, matrender::SettingScope scope, const std::string& group) {
  for (const matrender::RenderSettingDeclaration& setting : matrender::render_setting_declarations()) {
    if (setting.scope != scope || setting.name == "threads") continue;
    const std::string documentation(setting.documentation);
    if (setting.form == matrender::SettingForm::Switch) {
      const bool on_by_default = matrender::default_text(setting) == "true";
      const std::string option = on_by_default ? "--no-" + option_spelling(setting).substr(2) : option_spelling(setting);
      app.add_flag_callback(
             option, [&o, &setting, option, on_by_default] {
               o.render_settings.push_back({&setting, option, on_by_default ? "false" : "true"});
             },
             on_by_default ? "turn off (on by default): " + documentation : documentation)
          ->group(group);
      continue;
    }
    const std::string option = option_spelling(setting);
    add_setting_value_option(app, setting, option, group, [&o, &setting, option](const std::string& text, const auto&) {
      o.render_settings.push_back({&setting, option, text});
    });
  }
}

void add_render_options(CLI::App& app, Options& o) {
  const std::string group = "Render (override the scene file's render block)";
  add_setting_options(app, o, matrender::SettingScope::Scene, group);
  app.add_option_function<std::string>(
         "--exposure",
         [&o](const std::string& text) {
           if (text == "auto") {
             o.exposure_auto = true;
             return;
           }
           const std::optional<double> stops = matbase::finite_number(text);
           require(stops && std::abs(*stops) <= matbase::kMaxExposureStops, "--exposure",
                   fmt::format("\"auto\" or a number of stops in [{}, {}]", -matbase::kMaxExposureStops,
                               matbase::kMaxExposureStops));
           o.exposure = *stops;
         },
         "display PNG exposure in stops, or \"auto\": the grey-card rule (docs/make_dataset.md, \"Exposure\") for "
         "a card at the objects' centre facing the camera, under the scene's lamps and world")
      ->type_name("STOPS|auto")
      ->default_str("0")
      ->group(group);
  app.add_option_function<double>(
         "--illuminance",
         [&o](const double& lux) {
           require(lux > 0.0, "--illuminance", "a positive number of lux");
           o.illuminance_lux = lux;
         },
         "rescale the paper's light rig so the illuminance at its centre is this (lux); objects "
         "rendered without a scene file default to the paper's stated 1000 lx")
      ->type_name("LUX")
      ->group(group);
  app.add_flag("--paper-powers", o.paper_powers,
               "keep the powers of the paper's formula P = P_base (1 + 0.3 cos theta) as they are "
               "(about 1e5-1e6 lx at the object)")
      ->excludes("--illuminance")
      ->group(group);
}

void add_run_options(CLI::App& app, Options& o) {
  const std::string group = "Run";
  add_setting_value_option(app, matrender::render_setting("threads"), "--threads", group,
                           [&o](const std::string&, const matrender::RenderSettings& checked) { o.threads = checked.threads; });
  app.add_option("--texture-memory", o.texture_memory_mib,
                 "most memory the textures' texels may take, in MiB; past it the least recently used mip "
                 "levels are dropped and made again when needed (0 = half of this process's memory)")
      ->check(CLI::Range(uint64_t{0}, uint64_t{1} << 30))
      ->type_name("MIB")
      ->default_str("0")
      ->group(group);
  app.add_option_function<std::string>(
         "--aovs",
         [&o](const std::string& list) {
           o.aovs = parse_aov_list(list);
           o.aovs_given = true;
         },
         aov_help())
      ->type_name("LIST")
      ->default_str("default")
      ->group(group);
  app.add_option("--output", o.output_folder, "folder the images are written to (created if needed)")
      ->capture_default_str()
      ->type_name("DIR")
      ->group(group);
}

ObjectDescription object_from(std::variant<MeshFile, BuiltinObject> source, std::string option) {
  ObjectDescription object;
  std::visit([&object](auto& given) { object.source = std::move(given); }, source);
  object.origin = Origin{std::move(option), std::nullopt};
  return object;
}

uint32_t parse_seed(const std::string& text) {
  if (const std::optional<std::string> problem =
          matbase::whole_number_problem(text, 0, std::numeric_limits<uint32_t>::max()))
    throw matbase::InputError("--object: seed: " + *problem);
  return static_cast<uint32_t>(std::stoul(text));
}

// "NAME" or "NAME:SEED" as given to --object.
ObjectDescription builtin_object(const std::string& argument) {
  const size_t colon = argument.find(':');
  BuiltinObject builtin{argument.substr(0, colon), 0};
  const std::vector<std::string> names = matgeom::builtin_object_names();
  if (std::find(names.begin(), names.end(), builtin.name) == names.end())
    throw matbase::InputError("--object: unknown built-in object \"" + builtin.name + "\" (available: " + joined(names) + ")");
  if (colon != std::string::npos) builtin.seed = parse_seed(argument.substr(colon + 1));
  return object_from(builtin, "--object");
}

// The --mesh or --object, with the UV pass --uv-scale asks for.
ObjectDescription single_object(const Options& options) {
  ObjectDescription object = options.mesh_file
                                 ? object_from(MeshFile{*options.mesh_file, {options.auto_smooth_deg}}, "--mesh")
                                 : builtin_object(*options.object);
  if (options.uv_scale) {
    object.uv_pass = matrender::UvPassMode::Always;
    object.uv_scale = *options.uv_scale;
  }
  return object;
}

SceneDescription chosen_scene(const Options& options) {
  if (options.uv_scale && !options.mesh_file && !options.object)
    throw InputError("--uv-scale: needs --mesh or --object (a scene file gives each object its own \"uv_scale\")");
  if (options.scene_file) return matrender::read_scene_file(*options.scene_file);
  if (options.dataset_frame) {
    const matdataset::FrameScene frame = matdataset::dataset_frame_scene(*options.dataset_frame);
    return matrender::read_scene_text(frame.json, *options.dataset_frame + " (its scene)", frame.folder);
  }
  if (options.mesh_file || options.object) return matrender::paper_object_scene(single_object(options));
  return matrender::default_scene();
}

void apply_render_options(const Options& o, SceneDescription& scene) {
  matrender::RenderSettings& s = scene.settings;
  for (const Options::SettingOption& given : o.render_settings)
    if (const std::optional<std::string> problem = matrender::assign_text(s, *given.setting, given.value))
      throw InputError(given.option + ": " + *problem);
  if (const std::optional<matrender::SettingConflict> conflict = matrender::settings_conflict(s)) {
    // Named by the options that gave them, or by the scene file's keys.
    auto spelled = [&o](std::string_view name) {
      for (const Options::SettingOption& given : o.render_settings)
        if (given.setting->name == name) return given.option;
      return "the scene file's " + std::string(name);
    };
    throw InputError(matrender::conflict_refusal(*conflict, spelled(conflict->first), spelled(conflict->second)));
  }
  if (const std::optional<std::string> problem = matrender::denoising_problem(s.denoise))
    throw InputError("denoise: " + *problem);
  if (o.exposure) scene.exposure_stops = *o.exposure;
  s.threads = app_support::announced_worker_threads("render_object", "--threads", o.threads);
  // A dataset's frame takes the dataset's AOVs unless told otherwise.
  s.aovs = o.dataset_frame && !o.aovs_given ? matdataset::dataset_aovs() : o.aovs;
}

// The scene changes the options ask for, each named by its option.
matrender::SceneOverrides scene_overrides(const Options& o) {
  matrender::SceneOverrides overrides;
  if (o.camera_position) {
    if (*o.camera_position == *o.look_at)
      throw matbase::InputError("--look-at: expected a point different from --camera-position");
    overrides.placement = LookAtPlacement{*o.camera_position, *o.look_at, glm::dvec3(0.0, 0.0, 1.0)};
  }
  if (o.grid) overrides.grid = {*o.grid, "--grid"};
  if (o.radius) overrides.grid_radius = {*o.radius, "--radius"};
  if (o.cell) overrides.cell = {*o.cell, "--cell"};
  if (o.fov_deg) overrides.vertical_fov = glm::radians(*o.fov_deg);
  overrides.width = o.width;
  overrides.height = o.height;
  overrides.rig_at_given_powers = o.paper_powers;
  if (o.illuminance_lux) overrides.illuminance_lux = {*o.illuminance_lux, "--illuminance"};
  if (o.environment) {
    matrender::EnvironmentDescription environment;
    environment.path =
        matrender::is_builtin_environment(*o.environment) ? matrender::builtin_environment_path(*o.environment) : *o.environment;
    environment.origin = Origin{"--environment", std::nullopt};
    overrides.environment = environment;
  }
  if (o.sky) overrides.sky = matrender::SkyDescription{*o.sky, Origin{"--sky", std::nullopt}};
  if (o.environment_strength) overrides.environment_strength = {*o.environment_strength, "--environment-strength"};
  if (o.environment_rotation_deg)
    overrides.environment_rotation_z = {glm::radians(*o.environment_rotation_deg), "--environment-rotation"};
  // --material-dir or --material: one scene material, the folder's or the library's, on every
  // part of every object.
  if (o.material_dir || o.material) {
    const std::string name = o.material_dir ? "--material-dir" : "--material";
    matrender::MaterialDescription material;
    material.constants.name = name;
    if (o.material_dir)
      material.folder = matrender::MaterialFolderFile{*o.material_dir, Origin{name, std::nullopt}};
    else
      material.library = matrender::LibraryMaterialRequest{*o.material, o.material_resolution, Origin{name, std::nullopt}};
    overrides.materials[name] = material;
    overrides.material_everywhere = name;
  }
  return overrides;
}

}  // namespace

void add_options(CLI::App& app, Options& options) {
  add_scene_options(app, options);
  add_camera_options(app, options);
  add_render_options(app, options);
  add_run_options(app, options);
}

SceneDescription describe_scene(const Options& options) {
  SceneDescription scene = chosen_scene(options);
  matrender::apply_scene_overrides(scene_overrides(options), scene);
  apply_render_options(options, scene);
  return scene;
}

}  // namespace render_object
