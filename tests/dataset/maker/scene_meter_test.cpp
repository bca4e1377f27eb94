// The grey card measured in the scene (matdataset/maker/scene_meter.h): where nothing blocks or
// bounces it reads what the analytic meter computes, in a closed room it reads nothing of the
// world outside, and it leaves the scene's meshes as they were.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "matbase/pi.h"
#include "matdataset/maker/scene_meter.h"
#include "matgeom/bounding_sphere.h"
#include "matrender/light_meter.h"
#include "matrender/scene_builder.h"
#include "matrender/scene_file.h"

using namespace matdataset;

namespace {

// A vase at the origin in `room` (a scene file's room object), lit by `lights` under `background`,
// with the meter's card.
matrender::BuiltScene scene_with_card(const std::string& room, const std::string& lights, const std::string& background) {
  matrender::SceneDescription description = matrender::read_scene_text(
      R"({"camera": {"position": [3, 0, 1], "look_at": [0, 0, 0.2]},
          "materials": {"black": {"base_color": [0, 0, 0], "specular": 0}},
          "lights": )" + lights + R"(, "background": )" + background + R"(,
          "objects": [{"builtin": "vase"}, {"room": )" + room + R"(, "material": "black"}]})",
      "meter test", ".");
  description.objects.push_back(meter_card_object());
  description.materials.emplace(kMeterCardMaterial, meter_card_material());
  matrender::BuiltScene built = matrender::build_scene(description);
  built.scene.set_mesh_enabled(built.object_meshes.back(), false);
  return built;
}

matgeom::CameraGridSpec grid_about(const matrender::BuiltScene& built) {
  matgeom::CameraGridSpec grid;
  grid.center = built.centroid;
  grid.radius = 1.0;
  grid.n_phi = 3;
  grid.n_theta = 4;
  return grid;
}

}  // namespace

TEST_CASE("With nothing in the way the card reads what the analytic meter computes", "[dataset]") {
  // A point lamp and a spot above the vase; a black floor far below adds no bounce.
  const std::string lights = R"([{"type": "point", "position": [0.5, 0.2, 2.5], "power": 300},
                                 {"type": "spot", "position": [-1.5, 1, 2], "look_at": [0, 0, 0.2], "power": 500,
                                  "spot_angle_deg": 60}])";
  matrender::BuiltScene built = scene_with_card(R"({"floor_center": [0, 0, -0.5], "half_width": 20})", lights, "[0, 0, 0]");
  const matgeom::CameraGridSpec grid = grid_about(built);
  const double measured = meter_card_lux(built.scene, built.object_meshes.back(), {built.object_meshes.front()}, grid,
                                         -0.5, matrender::RenderSettings{});
  // The analytic reading of the same card directions: all 12 cells (fewer than 8 * 2).
  double expected = 0.0;
  int counted = 0;
  const std::vector<matgeom::GridCamera> cameras = matgeom::camera_grid(grid);
  for (size_t k = 0; k < 8; ++k) {
    const matgeom::GridCamera& camera = cameras[k * (cameras.size() - 1) / 7];
    const glm::dvec3 normal = glm::normalize(camera.position - grid.center);
    for (const matrender::Lamp& lamp : built.scene.lamps())
      expected += matrender::lamp_card_illuminance_lux(lamp, grid.center, normal);
    ++counted;
  }
  expected /= counted;
  REQUIRE(expected > 10.0);
  // 8 x 16 pixels x 64 samples of a lamp-lit Lambertian card: well within 3 %.
  CHECK(measured == Approx(expected).epsilon(0.03));
}

TEST_CASE("In a closed room the card reads nothing of the world outside; in an open one it does", "[dataset]") {
  const std::string box = R"({"floor_center": [0, 0, 0], "half_width": 2, "height": 2, "walls": "box", "ceiling": true})";
  matrender::BuiltScene closed = scene_with_card(box, "[]", "[1, 1, 1]");
  const uint32_t card = closed.object_meshes.back(), vase = closed.object_meshes.front();
  CHECK(meter_card_lux(closed.scene, card, {vase}, grid_about(closed), 0.0, matrender::RenderSettings{}) == 0.0);
  // The analytic meter knows no walls: it reads the whole sky.
  CHECK(matrender::grey_card_exposure(closed.scene.lamps(), closed.scene.background(), grid_about(closed)) < 0.0);
  // Every mesh as it was: the vase shown, the card hidden.
  CHECK(closed.scene.mesh_enabled(vase));
  CHECK_FALSE(closed.scene.mesh_enabled(card));

  matrender::BuiltScene open = scene_with_card(R"({"floor_center": [0, 0, 0], "half_width": 2, "height": 2, "walls": "box"})",
                                               "[]", "[1, 1, 1]");
  // A uniform sky of radiance 1 through the open top: some, and less than the whole sky's pi x 683.
  const double lux = meter_card_lux(open.scene, open.object_meshes.back(), {open.object_meshes.front()},
                                    grid_about(open), 0.0, matrender::RenderSettings{});
  CHECK(lux > 0.05 * 683.0 * matbase::kPi);
  CHECK(lux < 683.0 * matbase::kPi);
}
