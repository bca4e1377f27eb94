#include "matgeom/light_rig.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "matbase/pi.h"

namespace {

using matgeom::RigLight;
using matgeom::RigLightKind;

using matbase::kPi;
constexpr double kDegrees = kPi / 180.0;
constexpr double kLumensPerWatt = 683.0;
constexpr double kLuminanceOfLampColor = 0.8;  // Rec.709 Y of (0.8, 0.8, 0.8)

glm::dvec3 column(const glm::dmat4& m, int k) { return glm::dvec3(m[k]); }

void check_near(const glm::dvec3& actual, const glm::dvec3& expected, double tolerance = 1e-12) {
  INFO("actual (" << actual.x << ", " << actual.y << ", " << actual.z << "), expected ("
                  << expected.x << ", " << expected.y << ", " << expected.z << ")");
  CHECK(glm::length(actual - expected) <= tolerance);
}

// The rectangle of an area lamp, summed on an n x n midpoint grid:
// E = integral of L cos(receiver) cos(lamp) / d^2 dA with L = P Y / (4 a b), the receiver's
// normal pointing at the lamp centre. Returns lux.
double brute_force_area_lux(const RigLight& light, const glm::dvec3& point, int n) {
  const glm::dvec3 axis_x = column(light.light_to_world, 0);
  const glm::dvec3 axis_y = column(light.light_to_world, 1);
  const glm::dvec3 emit = -column(light.light_to_world, 2);
  const glm::dvec3 center = column(light.light_to_world, 3);
  const glm::dvec3 normal = glm::normalize(center - point);
  const double radiance = light.power * kLuminanceOfLampColor / (4.0 * light.size_x * light.size_y);
  const double cell_area = light.size_x * light.size_y / (double(n) * double(n));
  double sum = 0.0;
  for (int a = 0; a < n; ++a) {
    for (int b = 0; b < n; ++b) {
      const double x = ((a + 0.5) / n - 0.5) * light.size_x;
      const double y = ((b + 0.5) / n - 0.5) * light.size_y;
      const glm::dvec3 to_sample = center + x * axis_x + y * axis_y - point;
      const double d2 = glm::dot(to_sample, to_sample);
      const glm::dvec3 w = to_sample / std::sqrt(d2);
      const double cos_receiver = std::max(0.0, glm::dot(normal, w));
      const double cos_lamp = std::max(0.0, glm::dot(emit, -w));
      sum += cos_receiver * cos_lamp / d2;
    }
  }
  return kLumensPerWatt * radiance * sum * cell_area;
}

// Point on the normal through the centre of a parallel a x b rectangle at distance d: the
// classic view factor to a rectangle from a corner, F(X, Y) = 1/(2 pi) [X/sqrt(1+X^2)
// atan(Y/sqrt(1+X^2)) + Y/sqrt(1+Y^2) atan(X/sqrt(1+Y^2))], four times with X = a/2d,
// Y = b/2d; E = pi L F_total.
double centred_rectangle_irradiance(double radiance, double a, double b, double d) {
  const double x = a / (2.0 * d), y = b / (2.0 * d);
  const double corner = (x / std::sqrt(1 + x * x) * std::atan(y / std::sqrt(1 + x * x)) +
                         y / std::sqrt(1 + y * y) * std::atan(x / std::sqrt(1 + y * y))) /
                        (2.0 * kPi);
  return kPi * radiance * 4.0 * corner;
}

double expected_base_power(double r) { return 50.0 + 150.0 * std::min(1.0, r); }

// Independent of the library: E at c as the sum of brute-force area integrals and the spot
// formula I / d^2 (on axis, so the falloff is 1).
double brute_force_rig_lux(const std::vector<RigLight>& lights, const glm::dvec3& point) {
  double lux = 0.0;
  for (const RigLight& light : lights) {
    if (light.kind == RigLightKind::Area) {
      lux += brute_force_area_lux(light, point, 300);
    } else {
      const double d2 = glm::dot(light.position - point, light.position - point);
      lux += kLumensPerWatt * light.power * kLuminanceOfLampColor / (4.0 * kPi) / d2;
    }
  }
  return lux;
}

}  // namespace

TEST_CASE("ring size follows N = ceil(4 + 2r/0.25) clamped to [6, 12]", "[geom][render]") {
  struct Case {
    double radius;
    int ring;
    RigLightKind accent;
  };
  const Case cases[] = {
      {0.01, 6, RigLightKind::Spot}, {0.1, 6, RigLightKind::Spot},   // ceil(4.8) = 5 -> 6
      {0.15, 6, RigLightKind::Spot}, {0.16, 6, RigLightKind::Area},  // r = 0.15 m is a spot
      {0.3, 7, RigLightKind::Area},  {0.5, 8, RigLightKind::Area},   // ceil(6.4), ceil(8)
      {0.51, 9, RigLightKind::Area}, {0.8, 11, RigLightKind::Area},  // ceil(8.08), ceil(10.4)
      {1.0, 12, RigLightKind::Area}, {2.0, 12, RigLightKind::Area},  // 12, clamp(20)
  };
  for (const Case& c : cases) {
    INFO("r = " << c.radius);
    const matgeom::LightRig rig = matgeom::make_light_rig(glm::dvec3(0.0), c.radius);
    CHECK(rig.ring_count == c.ring);
    REQUIRE(rig.lights.size() == size_t(c.ring) + 2);
    int accents = 0;
    for (const RigLight& light : rig.lights) {
      if (!light.accent) {
        CHECK(light.kind == RigLightKind::Area);
        continue;
      }
      ++accents;
      CHECK(light.kind == c.accent);
    }
    CHECK(accents == 2);
    CHECK(rig.power_scale == 1.0);
  }
}

TEST_CASE("ring lamps: placement, size, orientation and power", "[geom][render]") {
  const glm::dvec3 c(0.4, -0.2, 1.3);
  for (const double r : {0.1, 0.5, 1.0, 2.0}) {
    INFO("r = " << r);
    const matgeom::LightRig rig = matgeom::make_light_rig(c, r);
    const int n = rig.ring_count;
    const double p_base = expected_base_power(r);
    for (int j = 0; j < n; ++j) {
      const RigLight& light = rig.lights[size_t(j)];
      REQUIRE_FALSE(light.accent);
      const double theta = 2.0 * kPi * j / n;
      CHECK(light.azimuth == Approx(theta).margin(1e-15));

      const glm::dvec3 expected_position =
          c + 2.0 * r * glm::dvec3(std::cos(theta), std::sin(theta), 0);
      check_near(light.position, expected_position);
      check_near(column(light.light_to_world, 3), expected_position);
      // On the horizontal circle of radius 2r through c.
      CHECK(light.position.z == Approx(c.z));
      CHECK(glm::distance(light.position, c) == Approx(2.0 * r));

      const glm::dvec3 x = column(light.light_to_world, 0);
      const glm::dvec3 y = column(light.light_to_world, 1);
      const glm::dvec3 z = column(light.light_to_world, 2);
      CHECK(glm::determinant(glm::dmat3(light.light_to_world)) == Approx(1.0));
      CHECK(std::abs(glm::dot(x, y)) < 1e-12);
      // -Z faces c; the long edge (+X) is horizontal and tangent to the circle.
      check_near(-z, glm::normalize(c - light.position));
      check_near(x, glm::dvec3(-std::sin(theta), std::cos(theta), 0.0));
      CHECK(std::abs(glm::dot(x, light.position - c)) < 1e-12);
      check_near(y, glm::dvec3(0, 0, 1));

      CHECK(light.size_x == Approx(0.6 * r));
      CHECK(light.size_y == Approx(0.3 * r));
      CHECK(light.power == Approx(p_base * (1.0 + 0.3 * std::cos(theta))));
      check_near(light.color, glm::dvec3(0.8));
    }
    // Cosine fall-off: the lamp at theta = 0 is the brightest, 1.3 P_base.
    CHECK(rig.lights[0].power == Approx(1.3 * p_base));
  }
  // P_base by hand: 50 + 150 * 0.5 = 125 W at r = 0.5; capped at 200 W from r = 1 m.
  CHECK(matgeom::make_light_rig(c, 0.5).lights[0].power == Approx(1.3 * 125.0));
  CHECK(matgeom::make_light_rig(c, 3.0).lights[0].power == Approx(1.3 * 200.0));
  // r = 0.5: N = 8, lamp 2 at theta = 90 degrees carries exactly P_base.
  CHECK(matgeom::make_light_rig(c, 0.5).lights[2].power == Approx(125.0));
  CHECK(matgeom::make_light_rig(c, 0.5).lights[4].power == Approx(0.7 * 125.0));
}

TEST_CASE("accent lamps at +-35 degrees, aimed at c", "[geom][render]") {
  const glm::dvec3 c(-1.0, 2.0, 0.5);
  for (const double r : {0.1, 0.15, 0.16, 0.7}) {
    INFO("r = " << r);
    const matgeom::LightRig rig = matgeom::make_light_rig(c, r);
    const RigLight& upper = rig.lights[size_t(rig.ring_count)];
    const RigLight& lower = rig.lights[size_t(rig.ring_count) + 1];
    const double e = 35.0 * kDegrees;
    check_near(upper.position, c + 2.0 * r * glm::dvec3(std::cos(e), 0.0, std::sin(e)));
    check_near(lower.position, c + 2.0 * r * glm::dvec3(std::cos(e), 0.0, -std::sin(e)));
    for (const RigLight* light : {&upper, &lower}) {
      CHECK(light->accent);
      CHECK(light->azimuth == 0.0);
      CHECK(light->power == Approx(expected_base_power(r)));
      check_near(-column(light->light_to_world, 2), glm::normalize(c - light->position));
      check_near(column(light->light_to_world, 0), glm::dvec3(0, 1, 0));
      CHECK(glm::determinant(glm::dmat3(light->light_to_world)) == Approx(1.0));
      if (r > 0.15) {
        CHECK(light->kind == RigLightKind::Area);
        CHECK(light->size_x == Approx(0.6 * r));
        CHECK(light->size_y == Approx(0.3 * r));
      } else {
        CHECK(light->kind == RigLightKind::Spot);
        CHECK(light->spot_angle == Approx(10.0 * kDegrees));
        CHECK(light->spot_blend == Approx(0.15));
      }
    }
  }
}

TEST_CASE("area lamp irradiance: polygon formula against closed form and brute force",
          "[geom][render]") {
  RigLight light;
  light.kind = RigLightKind::Area;
  light.size_x = 0.6;
  light.size_y = 0.3;
  light.power = 100.0;
  // Lamp at (0, 0, 2) facing down (-Z toward the origin): the identity frame translated.
  light.light_to_world[3] = glm::dvec4(0, 0, 2, 1);
  light.position = glm::dvec3(0, 0, 2);

  const double radiance = 100.0 * kLuminanceOfLampColor / (4.0 * 0.6 * 0.3);
  SECTION("on axis: the view-factor closed form") {
    const double expected = kLumensPerWatt * centred_rectangle_irradiance(radiance, 0.6, 0.3, 2.0);
    CHECK(matgeom::rig_illuminance_lux({light}, glm::dvec3(0.0)) ==
          Approx(expected).epsilon(1e-12));
    CHECK(brute_force_area_lux(light, glm::dvec3(0.0), 400) == Approx(expected).epsilon(1e-5));
  }
  SECTION("off axis and close: brute-force integration") {
    for (const glm::dvec3& point : {glm::dvec3(0.7, -0.4, 1.2), glm::dvec3(0.1, 0.05, 1.8),
                                    glm::dvec3(-2.0, 1.0, 0.0), glm::dvec3(0.0, 0.0, 1.95)}) {
      INFO("point (" << point.x << ", " << point.y << ", " << point.z << ")");
      CHECK(matgeom::rig_illuminance_lux({light}, point) ==
            Approx(brute_force_area_lux(light, point, 1000)).epsilon(2e-4));
    }
  }
  SECTION("one-sided: nothing behind the lamp or in its plane") {
    CHECK(matgeom::rig_illuminance_lux({light}, glm::dvec3(0, 0, 3)) == 0.0);
    CHECK(matgeom::rig_illuminance_lux({light}, glm::dvec3(1, 0, 2)) == 0.0);
  }
  SECTION("part of the lamp below the receiver's horizon") {
    // Close to the lamp's plane, over its +X end: the receiver faces the lamp centre, so the
    // corners at x = 0.3 lie behind its tangent plane (n . (corner - point) < 0); only the
    // visible part counts (the brute force clips through the max(0, cos) factor).
    const glm::dvec3 point(0.25, 0.0, 1.97);
    const glm::dvec3 normal = glm::normalize(light.position - point);
    REQUIRE(glm::dot(normal, glm::dvec3(0.3, 0.15, 2.0) - point) < 0.0);
    CHECK(matgeom::rig_illuminance_lux({light}, point) ==
          Approx(brute_force_area_lux(light, point, 2000)).epsilon(1e-3));
  }
}

TEST_CASE("spot lamp illuminance uses Cycles' intensity and falloff", "[geom][render]") {
  RigLight spot;
  spot.kind = RigLightKind::Spot;
  spot.power = 40.0;
  spot.spot_angle = 10.0 * kDegrees;
  spot.spot_blend = 0.15;
  spot.light_to_world[3] = glm::dvec4(0, 0, 3, 1);  // pointing down -Z
  spot.position = glm::dvec3(0, 0, 3);
  const double on_axis = kLumensPerWatt * 40.0 * kLuminanceOfLampColor / (4.0 * kPi) / 9.0;
  CHECK(matgeom::rig_illuminance_lux({spot}, glm::dvec3(0.0)) == Approx(on_axis));
  // Outside the 10 degree cone (half-angle 5 degrees): dark.
  CHECK(matgeom::rig_illuminance_lux({spot}, glm::dvec3(3.0 * std::tan(6.0 * kDegrees), 0, 0)) ==
        0.0);
  // Inside the cone but within the blend band: cos t * smoothstep.
  const double t = 4.99 * kDegrees;
  const glm::dvec3 point(3.0 * std::tan(t), 0.0, 0.0);
  const double cos_half = std::cos(5.0 * kDegrees);
  const double s = (std::cos(t) - cos_half) / ((1.0 - cos_half) * 0.15);
  REQUIRE(s < 1.0);
  const double d2 = 9.0 + point.x * point.x;
  const double expected = kLumensPerWatt * 40.0 * kLuminanceOfLampColor / (4.0 * kPi) / d2 *
                          std::cos(t) * s * s * (3.0 - 2.0 * s);
  CHECK(matgeom::rig_illuminance_lux({spot}, point) == Approx(expected).epsilon(1e-9));
}

TEST_CASE("rig illuminance at c against an independent sum", "[geom][render]") {
  const glm::dvec3 c(0.2, 0.3, 0.9);
  for (const double r : {0.1, 0.5, 1.0}) {
    INFO("r = " << r);
    const matgeom::LightRig rig = matgeom::make_light_rig(c, r);
    CHECK(rig.illuminance_lux == Approx(matgeom::rig_illuminance_lux(rig.lights, c)));
    CHECK(rig.illuminance_lux == Approx(brute_force_rig_lux(rig.lights, c)).epsilon(1e-4));
  }
  // Scale check by hand for r = 0.5: every ring lamp and area accent is 0.3 x 0.15 m at 1 m,
  // a small source: E ~ L * A = P Y / 4 per lamp. Sum of powers: 8 * 125 (the cosines cancel)
  // + 2 * 125 = 1250 W, so E ~ 683 * 0.8 * 1250 / 4 = 170.75 klx, a little less for the
  // finite size.
  const matgeom::LightRig rig = matgeom::make_light_rig(c, 0.5);
  CHECK(rig.illuminance_lux < 170750.0);
  CHECK(rig.illuminance_lux > 0.97 * 170750.0);
}

TEST_CASE("rig rescaled to a target illuminance", "[geom][render]") {
  const glm::dvec3 c(0.0, 0.0, 0.5);
  for (const double r : {0.05, 0.15, 0.4, 1.5}) {
    INFO("r = " << r);
    const matgeom::LightRig natural = matgeom::make_light_rig(c, r);
    matgeom::LightRigOptions options;
    options.target_illuminance_lux = 1000.0;
    const matgeom::LightRig scaled = matgeom::make_light_rig(c, r, options);
    CHECK(scaled.illuminance_lux == Approx(1000.0).epsilon(1e-12));
    CHECK(brute_force_rig_lux(scaled.lights, c) == Approx(1000.0).epsilon(1e-4));
    CHECK(scaled.power_scale == Approx(1000.0 / natural.illuminance_lux));
    REQUIRE(scaled.lights.size() == natural.lights.size());
    for (size_t k = 0; k < scaled.lights.size(); ++k) {
      CHECK(scaled.lights[k].power == Approx(natural.lights[k].power * scaled.power_scale));
    }
  }
}

TEST_CASE("light rig rejects bad input", "[geom][render]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(matgeom::make_light_rig(glm::dvec3(0.0), 0.0), std::invalid_argument);
  CHECK_THROWS_AS(matgeom::make_light_rig(glm::dvec3(0.0), -1.0), std::invalid_argument);
  CHECK_THROWS_AS(matgeom::make_light_rig(glm::dvec3(0.0), nan), std::invalid_argument);
  CHECK_THROWS_AS(matgeom::make_light_rig(glm::dvec3(nan, 0, 0), 1.0), std::invalid_argument);
  matgeom::LightRigOptions options;
  options.target_illuminance_lux = -5.0;
  CHECK_THROWS_AS(matgeom::make_light_rig(glm::dvec3(0.0), 1.0, options), std::invalid_argument);
}
