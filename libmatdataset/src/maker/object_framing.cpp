#include "matdataset/maker/object_framing.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "matbase/pi.h"
#include "matrender/scene_builder.h"

namespace matdataset {
namespace {

constexpr double kDegree = matbase::kPi / 180.0;

}  // namespace

matrender::ObjectDescription dataset_object_description(const DatasetConfig& config, size_t index, double uv_scale) {
  const ObjectConfig& object = config.objects[index];
  matrender::ObjectDescription description;
  std::visit([&description](const auto& source) { description.source = source; }, object.source);
  description.uv_pass = object.uv_pass;
  description.uv_scale = uv_scale;
  description.origin = matrender::Origin{config.source, "/objects/" + std::to_string(index)};
  return description;
}

double camera_grid_radius(const CameraConfig& camera, const matgeom::TriangleMesh& mesh, const matgeom::Sphere& bounds,
                          const glm::dvec3& centre, double aspect) {
  switch (camera.radius_rule) {
    case RadiusRule::Fixed:
      return camera.radius_m;
    case RadiusRule::BoundingBox: {
      glm::dvec3 low(mesh.positions.front()), high(mesh.positions.front());
      for (const glm::vec3& p : mesh.positions) low = glm::min(low, glm::dvec3(p)), high = glm::max(high, glm::dvec3(p));
      const glm::dvec3 extent = high - low;
      return std::max(camera.min_radius_m, camera.box_factor * std::max({extent.x, extent.y, extent.z}));
    }
    case RadiusRule::Fit:
    default: {
      // The sphere about the grid's centre that holds the bounding sphere, seen within the
      // narrower of the two fields of view.
      const double reach = glm::length(bounds.center - centre) + bounds.radius;
      const double vertical = camera.vertical_fov_deg * kDegree;
      const double horizontal = 2.0 * std::atan(aspect * std::tan(0.5 * vertical));
      return reach / std::sin(0.5 * std::min(vertical, horizontal)) / camera.fill;
    }
  }
}

ObjectFraming object_framing(const DatasetConfig& config, const matgeom::TriangleMesh& surface) {
  const CameraConfig& camera = config.camera;
  ObjectFraming framing;
  framing.bounds = matgeom::minimal_enclosing_sphere(surface.positions);
  matgeom::CameraGridSpec& grid = framing.grid;
  grid.center = matgeom::surface_centroid(surface);
  grid.radius = camera_grid_radius(camera, surface, framing.bounds, grid.center,
                                   static_cast<double>(config.render.width) / config.render.height);
  grid.phi_min = camera.phi_min_deg * kDegree;
  grid.phi_max = camera.phi_max_deg * kDegree;
  grid.theta_min = camera.theta_min_deg * kDegree;
  grid.theta_max = camera.theta_max_deg * kDegree;
  grid.n_phi = camera.n_phi;
  grid.n_theta = camera.n_theta;
  return framing;
}

std::vector<size_t> grid_views_under_floor(const DatasetConfig& config, size_t index) {
  if (!config.objects[index].surroundings.made_room() || config.camera.phi_max_deg <= 90.0) return {};
  const matgeom::TriangleMesh surface = matrender::placed_object_surface(
      dataset_object_description(config, index, config.objects[index].uv_scales.front()));
  const matgeom::CameraGridSpec grid = object_framing(config, surface).grid;
  const double floor = floor_height(surface, grid);
  std::vector<size_t> under;
  for (const matgeom::GridCamera& camera : matgeom::camera_grid(grid))
    if (!(camera.position.z > floor))
      under.push_back(static_cast<size_t>(camera.i) * static_cast<size_t>(grid.n_theta) + static_cast<size_t>(camera.j));
  return under;
}

}  // namespace matdataset
