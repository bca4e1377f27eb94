#include "matdataset/maker/scene_meter.h"

#include <memory>

#include <glm/gtc/matrix_transform.hpp>

#include "matbase/image/srgb.h"
#include "matbase/pi.h"
#include "matgeom/object_asset.h"
#include "matrender/camera.h"
#include "matrender/frame.h"
#include "matrender/render.h"

namespace matdataset {
namespace {

// The card seen head-on from this far in front (in half-sides) through this field of view shows
// only itself: the frame spans tan(10 degrees) x 2 = 0.35 of the half-side.
constexpr double kViewDistance = 2.0;
constexpr double kViewFovDeg = 20.0;
constexpr int kPixels = 4;
constexpr int kSamples = 64;
// The card's half-side in grid radii: small beside anything in the room.
constexpr double kHalfSide = 0.01;

}  // namespace

matrender::MaterialDescription meter_card_material() {
  matrender::MaterialDescription card;
  card.constants.name = kMeterCardMaterial;
  card.constants.diffuse_model = matrender::DiffuseModel::Lambert;
  card.constants.set(matrender::MaterialParameter::BaseColor, glm::vec3(1.0f));
  card.constants.set(matrender::MaterialParameter::Specular, 0.0f);
  card.constants.set(matrender::MaterialParameter::Roughness, 1.0f);
  return card;
}

matrender::ObjectDescription meter_card_object() {
  auto asset = std::make_shared<matgeom::ObjectAsset>();
  matgeom::TriangleMesh& mesh = asset->mesh;
  mesh.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  mesh.normals.assign(4, glm::vec3(0, 0, 1));
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  mesh.part_names = {"card"};
  asset->materials.emplace_back("card");
  matrender::ObjectDescription card;
  card.source = matrender::GivenObject{asset};
  card.material = kMeterCardMaterial;
  card.surroundings = true;
  return card;
}

double meter_card_lux(matrender::Scene& scene, uint32_t card, const std::vector<uint32_t>& hidden,
                      const matgeom::CameraGridSpec& grid, double floor_z, const matrender::RenderSettings& settings,
                      int directions) {
  std::vector<bool> was_enabled;
  for (const uint32_t mesh : hidden) {
    was_enabled.push_back(scene.mesh_enabled(mesh));
    scene.set_mesh_enabled(mesh, false);
  }
  scene.set_mesh_enabled(card, true);
  const std::vector<matgeom::GridCamera> cameras = matgeom::camera_grid(grid);
  matrender::RenderSettings meter;
  meter.max_bounces = settings.max_bounces;
  meter.max_diffuse_bounces = settings.max_diffuse_bounces;
  meter.max_glossy_bounces = settings.max_glossy_bounces;
  meter.max_transmission_bounces = settings.max_transmission_bounces;
  meter.max_transparent_bounces = settings.max_transparent_bounces;
  meter.samples_per_pixel = kSamples;
  meter.threads = settings.threads;
  meter.aovs = 0;
  const double half_side = kHalfSide * grid.radius;
  double total_lux = 0.0;
  int measured = 0;
  const size_t count = cameras.size(), wanted = static_cast<size_t>(directions);
  for (size_t k = 0; k < std::min(count, wanted); ++k) {
    // Spread over the cells: the first, the last and evenly between.
    const size_t index = wanted >= count ? k : (wanted == 1 ? count / 2 : k * (count - 1) / (wanted - 1));
    const matgeom::GridCamera& camera = cameras[index];
    if (!(camera.position.z > floor_z)) continue;
    // The camera's own frame, moved to the centre: the card's +Z faces the camera.
    glm::dmat4 place = camera.camera_to_world;
    place[3] = glm::dvec4(grid.center, 1.0);
    scene.set_mesh_transform(card, glm::scale(place, glm::dvec3(half_side)));
    const glm::dvec3 facing = glm::normalize(glm::dvec3(camera.camera_to_world[2]));
    const matrender::Camera view = matrender::Camera::look_at(
        grid.center + kViewDistance * half_side * facing, grid.center, glm::dvec3(camera.camera_to_world[1]),
        kViewFovDeg * matbase::kPi / 180.0, kPixels, kPixels);
    meter.seed = static_cast<uint32_t>(index);
    matrender::FrameBuffers frame;
    matrender::render(scene, view, meter, frame);
    double luminance = 0.0;
    for (size_t p = 0; p + 2 < frame.color.size(); p += 3)
      luminance += matbase::rec709_luminance(glm::dvec3(frame.color[p], frame.color[p + 1], frame.color[p + 2]));
    luminance /= kPixels * kPixels;
    // A white Lambertian card of illuminance E shows luminance E / (683 pi) (Blender's units).
    total_lux += 683.0 * matbase::kPi * luminance;
    ++measured;
  }
  scene.set_mesh_enabled(card, false);
  for (size_t k = 0; k < hidden.size(); ++k) scene.set_mesh_enabled(hidden[k], was_enabled[k]);
  return measured > 0 ? total_lux / measured : 0.0;
}

}  // namespace matdataset
