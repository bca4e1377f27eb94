#pragma once
// Changes a tool makes to a described scene (matrender/scene_description.h) before it is built:
// the camera's placement, grid, field of view and image size; the paper's rig's illuminance; the
// background's environment map; materials added, and one of them on every part. render_object
// takes them from its options, make_dataset from its configuration. Each change that can be
// refused carries the name of what asked for it (an option, a configuration key), which the
// refusal opens with.
#include <array>
#include <map>
#include <optional>
#include <string>

#include "matrender/scene_description.h"

namespace matrender {

// A value and what asked for it ("--grid", "objects.0").
template <class T>
struct Requested {
  T value;
  std::string by;
};

struct SceneOverrides {
  // A placement replaces the scene's camera. Any of grid, grid_radius and cell then makes the
  // camera a grid camera: the scene's own grid if it has one, else the paper's grid about the
  // objects' centroid (paper_grid_placement).
  std::optional<CameraPlacement> placement;
  std::optional<Requested<std::array<int, 2>>> grid;  // n_phi, n_theta
  std::optional<Requested<double>> grid_radius;       // metres
  std::optional<Requested<std::array<int, 2>>> cell;  // i, j of the grid's views
  std::optional<double> vertical_fov;                 // radians
  std::optional<int> width, height;                   // pixels

  // The paper's rig at its lamps' own powers (no illuminance target), or scaled so the object
  // receives this illuminance. Lights listed by a scene file take neither.
  bool rig_at_given_powers = false;
  std::optional<Requested<double>> illuminance_lux;

  // An environment map in place of the background; its strength and turn about Z (radians),
  // which need a map: this one or the scene's.
  std::optional<EnvironmentDescription> environment;
  std::optional<SkyDescription> sky;  // a sky in place of the background (no strength or turn applies)
  std::optional<Requested<double>> environment_strength;
  std::optional<Requested<double>> environment_rotation_z;

  // Materials added to the scene's by name (replacing one of the same name), and the name of one
  // of the scene's materials to put on every part of every object.
  std::map<std::string, MaterialDescription> materials;
  std::optional<std::string> material_everywhere;
};

// Applies every override to `scene`. Throws matbase::InputError, opening with what asked, for a
// grid cell outside its grid, an illuminance for a scene whose lights are listed, and a strength
// or turn with no environment map to apply it to; std::invalid_argument for
// material_everywhere naming no material of the scene.
void apply_scene_overrides(const SceneOverrides& overrides, SceneDescription& scene);

}  // namespace matrender
