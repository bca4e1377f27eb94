#pragma once
// render_object's command line: the options, and the scene they ask for.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "matrender/frame.h"
#include "matrender/render.h"
#include "matrender/scene_description.h"
#include "matrender/sky.h"

namespace CLI {
class App;
}

namespace render_object {

struct Options {
  // What to render: at most one of these; none renders the built-in default scene.
  std::optional<std::string> scene_file;
  std::optional<std::string> mesh_file;
  std::optional<double> auto_smooth_deg;  // --auto-smooth, for --mesh
  std::optional<double> uv_scale;         // --uv-scale, for --mesh or --object
  std::optional<std::string> object;  // NAME[:SEED]
  std::optional<std::string> dataset_frame;  // a make_dataset frame: VARIANT_FOLDER/STEM
  bool list_objects = false;
  bool list_parameters = false;
  bool list_settings = false;
  bool list_materials = false;
  std::optional<std::string> material_dir;  // every object in this material folder
  std::optional<matmaterial::LibraryMaterialSpec> material;  // every object in this library material
  int material_resolution = matrender::LibraryMaterialRequest::kDefaultLibraryResolution;
  std::optional<std::string> environment;  // replaces the scene's background
  std::optional<matrender::NishitaSky> sky;  // replaces the scene's background
  std::optional<double> environment_strength;
  std::optional<double> environment_rotation_deg;

  // A render setting given on the command line (matrender/render_setting_declarations.h): checked
  // against its declaration when read, applied over the scene file's in the order given.
  struct SettingOption {
    const matrender::RenderSettingDeclaration* setting;
    std::string option;  // as typed: "--spp"
    std::string value;   // as assign_text reads it
  };
  std::vector<SettingOption> render_settings;

  // Each set value overrides the scene's (the scene file's camera and render block).
  std::optional<int> width;
  std::optional<int> height;
  std::optional<std::array<int, 2>> cell;
  std::optional<std::array<int, 2>> grid;  // n_phi, n_theta
  std::optional<double> radius;
  std::optional<glm::dvec3> camera_position;
  std::optional<glm::dvec3> look_at;
  std::optional<double> fov_deg;
  std::optional<double> exposure;
  bool exposure_auto = false;  // --exposure auto: metered by the grey-card rule
  std::optional<double> illuminance_lux;
  bool paper_powers = false;

  // The run itself.
  int threads = 0;  // 0 = all hardware threads
  uint64_t texture_memory_mib = 0;  // 0 = matrender::default_texture_memory_limit()
  uint32_t aovs = matrender::default_aovs();
  bool aovs_given = false;
  std::string output_folder = "./render_out";
};

void add_options(CLI::App& app, Options& options);

// The scene file, --mesh, --object or the built-in default, with the overrides applied.
// Throws matbase::InputError.
matrender::SceneDescription describe_scene(const Options& options);

}  // namespace render_object
