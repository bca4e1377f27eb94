#include "matrender/rig_lights.h"

#include <variant>

#include <catch2/catch.hpp>

// The rig's lamps keep their placement, size and power as libmatrender lamps, and spots shine
// down their local -Z like every Blender lamp.
TEST_CASE("rig_lights: area lights become rectangles, accents for small objects become spots", "[render]") {
  for (const double radius : {0.1, 0.5}) {
    const matgeom::LightRig rig = matgeom::make_light_rig(glm::dvec3(0.2, -0.1, 0.4), radius);
    const std::vector<matrender::Light> lights = matrender::rig_lights(rig);
    REQUIRE(lights.size() == rig.lights.size());
    size_t spots = 0;
    for (size_t k = 0; k < lights.size(); ++k) {
      const matgeom::RigLight& source = rig.lights[k];
      if (source.kind == matgeom::RigLightKind::Area) {
        const auto& rect = std::get<matrender::RectLight>(lights[k]);
        CHECK(rect.light_to_world == source.light_to_world);
        CHECK(rect.size_x == source.size_x);
        CHECK(rect.size_y == source.size_y);
        CHECK(rect.power == source.power);
        CHECK(rect.color == source.color);
      } else {
        const auto& spot = std::get<matrender::SpotLight>(lights[k]);
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
