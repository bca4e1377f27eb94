#include "matrender/rig_lamps.h"

#include <cmath>
#include <variant>

#include <catch2/catch.hpp>

#include "matbase/pi.h"
#include "matrender/paper_setup.h"
#include "matrender/render.h"
#include "test_scenes.h"

// The rig's lamps keep their placement, size and power as libmatrender lamps, and spots shine
// down their local -Z like every Blender lamp.
TEST_CASE("rig_lamps: area lights become rectangles, accents for small objects become spots", "[render]") {
  for (const double radius : {0.1, 0.5}) {
    const matgeom::LightRig rig = matgeom::make_light_rig(glm::dvec3(0.2, -0.1, 0.4), radius);
    const std::vector<matrender::Lamp> lights = matrender::rig_lamps(rig);
    REQUIRE(lights.size() == rig.lights.size());
    size_t spots = 0;
    for (size_t k = 0; k < lights.size(); ++k) {
      const matgeom::RigLight& source = rig.lights[k];
      if (source.kind == matgeom::RigLightKind::Area) {
        const auto& rect = std::get<matrender::RectLamp>(lights[k]);
        CHECK(rect.light_to_world == source.light_to_world);
        CHECK(rect.size_x == source.size_x);
        CHECK(rect.size_y == source.size_y);
        CHECK(rect.power == source.power);
        CHECK(rect.color == source.color);
      } else {
        const auto& spot = std::get<matrender::SpotLamp>(lights[k]);
        ++spots;
        CHECK(spot.position == source.position);
        // The spot points from its position toward the rig centre.
        const glm::dvec3 to_centre = glm::normalize(glm::dvec3(0.2, -0.1, 0.4) - source.position);
        CHECK(glm::dot(spot.direction, to_centre) == Approx(1.0).epsilon(1e-9));
        CHECK(spot.spot_angle == source.spot_angle);
        CHECK(spot.blend == source.spot_blend);
        CHECK(spot.power == source.power);
      }
    }
    CHECK((spots > 0) == (radius <= 0.15));  // the accents are spots only for small objects
  }
}

// The grey-card exposure, checked against the renderer rather than against its own formula: a
// small Lambertian card at the grid's centre, facing the grid's one camera, rendered under the
// paper's rig (area accents for a large object, spot accents for a small one) and scaled by the
// exposure, shows half its albedo (one stop in hand).
TEST_CASE("grey_card_exposure makes a card facing the camera show half its albedo", "[render]") {
  for (const double object_radius : {0.1, 0.4}) {
    const glm::dvec3 centre(0.1, 0.2, 0.3);
    const matgeom::LightRig rig = matrender::paper_rig(matgeom::Sphere{centre, object_radius});
    matgeom::CameraGridSpec grid;
    grid.center = centre;
    grid.radius = 3.0;
    grid.phi_min = 50.0 * matbase::kPi / 180.0, grid.phi_max = 70.0 * matbase::kPi / 180.0;
    grid.theta_min = 10.0 * matbase::kPi / 180.0, grid.theta_max = 30.0 * matbase::kPi / 180.0;
    grid.n_phi = grid.n_theta = 1;
    const double stops = matrender::grey_card_exposure(rig, grid);

    constexpr float kAlbedo = 0.5f;
    const double card_side = 0.01 * object_radius;
    const matrender::Camera camera =
        matrender::grid_view(grid, 0, 0, 8, 8, 0.5 * card_side / grid.radius);  // the card fills the view
    matgeom::TriangleMesh card = test_scenes::horizontal_square(card_side);
    const glm::dmat3 facing_camera(camera.camera_to_world);  // its +Z points at the camera
    for (glm::vec3& p : card.positions) p = glm::vec3(centre + facing_camera * glm::dvec3(p));
    matrender::Scene scene;
    scene.add_mesh(card, {scene.add_material(test_scenes::lambert(kAlbedo))});
    matrender::add_rig(scene, rig);
    matrender::RenderSettings settings;
    settings.samples_per_pixel = 1024;
    matrender::FrameBuffers frame;
    matrender::render(scene, camera, settings, frame);
    double luminance = 0.0;
    for (size_t i = 0; i < frame.alpha.size(); ++i) {
      REQUIRE(frame.alpha[i] == 1.0f);
      luminance += 0.2126 * frame.color[3 * i] + 0.7152 * frame.color[3 * i + 1] + 0.0722 * frame.color[3 * i + 2];
    }
    luminance /= static_cast<double>(frame.alpha.size());
    CAPTURE(object_radius, stops);
    // 64 pixels x 1024 samples: the mean's noise is far below 1 %.
    CHECK(luminance * std::exp2(stops) == Approx(0.5 * kAlbedo).epsilon(0.01));
  }
}
