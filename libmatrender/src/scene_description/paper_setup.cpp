#include "matrender/paper_setup.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "matbase/image/image_writing.h"
#include "matbase/pi.h"
#include "matrender/light_meter.h"
#include "matrender/rig_lamps.h"

namespace matrender {

matgeom::LightRig paper_rig(const matgeom::Sphere& bounds, std::optional<double> target_lux) {
  matgeom::LightRigOptions options;
  options.target_illuminance_lux = target_lux;
  return matgeom::make_light_rig(bounds.center, bounds.radius, options);
}

matgeom::LightRig paper_rig(const matgeom::TriangleMesh& surface, std::optional<double> target_lux) {
  return paper_rig(matgeom::minimal_enclosing_sphere(surface.positions), target_lux);
}

double grey_card_exposure(const matgeom::LightRig& rig, const matgeom::CameraGridSpec& grid) {
  return grey_card_exposure(rig_lamps(rig), glm::vec3(0.0f), grid);
}

void add_rig(Scene& scene, const matgeom::LightRig& rig) {
  for (const Lamp& light : rig_lamps(rig)) scene.add_lamp(light);
}

Camera grid_view(const matgeom::CameraGridSpec& grid, int i, int j, int width, int height, double vertical_fov) {
  Camera camera;
  camera.camera_to_world = matgeom::grid_camera(grid, i, j).camera_to_world;
  camera.vertical_fov = vertical_fov;
  camera.width = width;
  camera.height = height;
  return camera;
}

std::vector<NamedView> grid_views(const matgeom::CameraGridSpec& grid, int width, int height, double vertical_fov) {
  std::vector<NamedView> views;
  for (int i = 0; i < grid.n_phi; ++i)
    for (int j = 0; j < grid.n_theta; ++j) views.push_back({view_name(i, j), grid_view(grid, i, j, width, height, vertical_fov)});
  return views;
}

std::string view_name(int i, int j) { return fmt::format("view_{:03d}_{:03d}", i, j); }

Camera paper_view(const matgeom::TriangleMesh& surface, int width, int height) {
  matgeom::CameraGridSpec grid;
  grid.center = matgeom::surface_centroid(surface);
  return grid_view(grid, kPaperViewRow, kPaperViewColumn, width, height);
}

GridPlacement paper_grid_placement() {
  GridPlacement grid;  // matgeom::CameraGridSpec's defaults are the paper's grid
  grid.center_on_centroid = true;
  grid.i = kPaperViewRow;
  grid.j = kPaperViewColumn;
  return grid;
}

SceneDescription paper_object_scene(ObjectDescription object) {
  SceneDescription scene;
  scene.camera.placement = paper_grid_placement();
  LightRigDescription rig;
  rig.target_illuminance_lux = kPaperTargetIlluminanceLux;
  scene.lights = rig;
  scene.objects.push_back(std::move(object));
  return scene;
}

SceneDescription default_scene() {
  ObjectDescription vase;
  vase.source = BuiltinObject{"vase", 0};
  vase.origin = Origin{"the default scene", std::nullopt};
  return paper_object_scene(std::move(vase));
}

}  // namespace matrender
