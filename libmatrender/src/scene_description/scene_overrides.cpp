#include "matrender/scene_overrides.h"

#include <stdexcept>

#include <fmt/format.h>

#include "matbase/input_error.h"
#include "matrender/paper_setup.h"

namespace matrender {
namespace {

void apply_camera(const SceneOverrides& o, CameraDescription& camera) {
  if (o.placement) camera.placement = *o.placement;
  if (o.grid || o.grid_radius || o.cell) {
    if (!std::holds_alternative<GridPlacement>(camera.placement)) camera.placement = paper_grid_placement();
    auto& grid = std::get<GridPlacement>(camera.placement);
    if (o.grid) {
      grid.spec.n_phi = o.grid->value[0];
      grid.spec.n_theta = o.grid->value[1];
    }
    if (o.grid_radius) grid.spec.radius = o.grid_radius->value;
    if (o.cell) {
      grid.i = o.cell->value[0];
      grid.j = o.cell->value[1];
    }
    if (grid.i >= grid.spec.n_phi || grid.j >= grid.spec.n_theta) {
      const std::string& by = o.cell ? o.cell->by : o.grid ? o.grid->by : o.grid_radius->by;
      throw matbase::InputError(fmt::format("{}: camera cell {},{} is outside the {} x {} grid", by, grid.i, grid.j,
                                            grid.spec.n_phi, grid.spec.n_theta));
    }
  }
  if (o.vertical_fov) camera.vertical_fov = *o.vertical_fov;
  if (o.width) camera.width = *o.width;
  if (o.height) camera.height = *o.height;
}

void apply_lights(const SceneOverrides& o, LightsDescription& lights) {
  auto* rig = std::get_if<LightRigDescription>(&lights);
  if (o.rig_at_given_powers) {
    if (rig) rig->target_illuminance_lux.reset();
    return;
  }
  if (!o.illuminance_lux) return;
  if (!rig)
    throw matbase::InputError(o.illuminance_lux->by +
                              ": rescales only the paper's light rig, and the scene file lists its own lights");
  rig->target_illuminance_lux = o.illuminance_lux->value;
}

void apply_background(const SceneOverrides& o, BackgroundDescription& background) {
  if (o.environment) background = *o.environment;
  if (o.sky) background = *o.sky;
  if (!o.environment_strength && !o.environment_rotation_z) return;
  auto* environment = std::get_if<EnvironmentDescription>(&background);
  if (!environment)
    throw matbase::InputError((o.environment_strength ? o.environment_strength : o.environment_rotation_z)->by +
                              ": the scene has no environment map (add one to the scene)");
  if (o.environment_strength) environment->strength = o.environment_strength->value;
  if (o.environment_rotation_z) environment->rotation_z = o.environment_rotation_z->value;
}

void apply_materials(const SceneOverrides& o, SceneDescription& scene) {
  for (const auto& [name, material] : o.materials) scene.materials[name] = material;
  if (!o.material_everywhere) return;
  if (!scene.materials.count(*o.material_everywhere))
    throw std::invalid_argument("the scene has no material \"" + *o.material_everywhere + "\" to put on every part");
  for (ObjectDescription& object : scene.objects) {
    object.material = *o.material_everywhere;
    object.part_materials.clear();
  }
}

}  // namespace

void apply_scene_overrides(const SceneOverrides& overrides, SceneDescription& scene) {
  apply_camera(overrides, scene.camera);
  apply_lights(overrides, scene.lights);
  apply_background(overrides, scene.background);
  apply_materials(overrides, scene);
}

}  // namespace matrender
