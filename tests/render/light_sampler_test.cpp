// The light set: which lights next-event estimation draws and with what probability, which ones
// rays find by themselves, and what a ray that leaves the scene sees.
#include <catch2/catch.hpp>

#include <variant>
#include <vector>

#include "lights/light_sampler.h"
#include "matbase/pi.h"
#include "uniform_floats.h"

using namespace matrender;

namespace {

RectLamp rect_at(double x) {
  RectLamp lamp;
  lamp.light_to_world[3] = glm::dvec4(x, 0.0, 1.0, 1.0);
  lamp.size_x = lamp.size_y = 0.5;
  return lamp;
}

}  // namespace

TEST_CASE("The distribution holds the lights by type: area, delta, infinite, not the uniform background", "[render]") {
  PointLamp soft_point;
  soft_point.radius = 0.1;
  SpotLamp soft_spot;
  soft_spot.radius = 0.2;
  SunLamp soft_sun;
  soft_sun.angle = 0.01;
  const std::vector<Lamp> lights = {PointLamp{}, soft_sun, SunLamp{}, rect_at(0.0), soft_spot, SpotLamp{},
                                     rect_at(2.0), soft_point};
  const LightSampler sampler(lights, UniformBackground(glm::vec3(0.1f, 0.2f, 0.3f)));
  REQUIRE(sampler.sampled_count() == 8);
  CHECK(std::holds_alternative<RectLight>(sampler.light(0)));
  CHECK(std::holds_alternative<RectLight>(sampler.light(1)));
  CHECK(std::holds_alternative<DiskLight>(sampler.light(2)));
  CHECK(std::holds_alternative<DiskLight>(sampler.light(3)));
  CHECK(light_type(sampler.light(3)) == LightType::Area);
  CHECK(std::holds_alternative<PointLight>(sampler.light(4)));
  CHECK(std::holds_alternative<SpotLight>(sampler.light(5)));
  CHECK(light_type(sampler.light(5)) == LightType::DeltaPosition);
  // A sun of angle 0 is one direction, one with an angle a disk of directions rays see.
  CHECK(std::holds_alternative<DistantLight>(sampler.light(6)));
  CHECK(light_type(sampler.light(6)) == LightType::DeltaDirection);
  CHECK(std::holds_alternative<SunLight>(sampler.light(7)));
  CHECK(light_type(sampler.light(7)) == LightType::Infinite);
  // The background is a ninth light, outside the distribution.
  CHECK(std::holds_alternative<UniformBackground>(sampler.light(8)));
  CHECK(sampler.has_area_lights());
}

TEST_CASE("Rays find the disks of lamps with a radius, facing their origin, within their length", "[render]") {
  PointLamp soft;
  soft.position = glm::dvec3(0.0, 0.0, 1.0);
  soft.radius = 0.2;
  const LightSampler sampler({soft}, UniformBackground(glm::vec3(0.0f)));
  const auto hits = [&](glm::vec3 origin, glm::vec3 dir, float t_max) {
    std::vector<float> ts;
    sampler.for_each_area_hit(origin, glm::normalize(dir), t_max, [&](size_t, const auto&, float t) { ts.push_back(t); });
    return ts;
  };
  CHECK(hits({0, 0, 0}, {0, 0, 1}, 10.0f) == std::vector<float>{1.0f});
  // The disk turns to face the origin: from the side it is still 0.2 wide.
  CHECK(hits({3, 0, 1}, {-1, 0.06f, 0}, 10.0f).size() == 1);
  CHECK(hits({3, 0, 1}, {-1, 0.07f, 0}, 10.0f).empty());
  CHECK(hits({0, 0, 0}, {0, 0, 1}, 0.99f).empty());
  CHECK(hits({0, 0, 0}, {0, 0, -1}, 10.0f).empty());
}

TEST_CASE("A uniform pick chooses each light over an equal interval and rescales u", "[render]") {
  const LightSampler sampler({rect_at(0.0), PointLamp{}, SpotLamp{}}, UniformBackground(glm::vec3(0.0f)),
                             LightSelection::Uniform);
  const PickSite site = sampler.site(glm::vec3(0.0f), {});
  for (int k = 0; k < 3; ++k)
    for (double within : {0.0, 0.25, 0.5, 0.75}) {
      float u = static_cast<float>((k + within) / 3.0);
      const auto picked = sampler.pick(site, &u);
      REQUIRE(picked);
      CHECK(picked->index == static_cast<size_t>(k));
      CHECK(picked->probability == Approx(1.0 / 3.0));
      CHECK(u == Approx(within).margin(1e-6));
    }
  float last = 0x1.fffffep-1f;
  const auto picked = sampler.pick(site, &last);
  REQUIRE(picked);
  CHECK(picked->index == 2);
  CHECK(last < 1.0f);
}

TEST_CASE("An importance pick chooses each light in proportion to its importance and rescales u", "[render]") {
  // Two point lamps, one four times as far from the site: 16 times less irradiance; a rectangle
  // facing away from the site can give it nothing and is never picked.
  RectLamp away = rect_at(0.0);  // emits down -Z, the site is above it
  const std::vector<Lamp> lights = {away, PointLamp{glm::dvec3(0.0, 0.0, 2.0), 10.0, glm::dvec3(1.0)},
                                     PointLamp{glm::dvec3(0.0, 0.0, 5.0), 10.0, glm::dvec3(1.0)}};
  const LightSampler sampler(lights, UniformBackground(glm::vec3(0.0f)));
  const PickSite site = sampler.site(glm::vec3(0.0f, 0.0f, 1.0f), {glm::vec3(0.0f, 0.0f, 1.0f), false});
  const double near = 10.0 / (4.0 * matbase::kPi) / 1.0, far = 10.0 / (4.0 * matbase::kPi) / 16.0;
  CHECK(site.total_importance == Approx(near + far).epsilon(1e-5));
  REQUIRE(std::holds_alternative<RectLight>(sampler.light(0)));
  CHECK(sampler.pick_probability(0, site) == 0.0f);
  REQUIRE(std::holds_alternative<PointLight>(sampler.light(1)));
  CHECK(sampler.pick_probability(1, site) == Approx(16.0 / 17.0));
  for (double within : {0.0, 0.3, 0.9}) {
    float u = static_cast<float>(within * 16.0 / 17.0);
    auto picked = sampler.pick(site, &u);
    REQUIRE(picked);
    CHECK(picked->index == 1);
    CHECK(u == Approx(within).margin(1e-5));
    u = static_cast<float>((16.0 + within) / 17.0);
    picked = sampler.pick(site, &u);
    REQUIRE(picked);
    CHECK(picked->index == 2);
    CHECK(picked->probability == Approx(1.0 / 17.0));
    CHECK(u == Approx(within).margin(1e-4));
  }
  // Below the plane of a reflecting BSDF nothing can light it: no pick.
  const PickSite under = sampler.site(glm::vec3(0.0f, 0.0f, 1.0f), {glm::vec3(0.0f, 0.0f, -1.0f), false});
  float u = 0.5f;
  CHECK(under.total_importance == 0.0f);
  CHECK_FALSE(sampler.pick(under, &u));
}

TEST_CASE("Importance is positive wherever a light can light a point", "[render]") {
  // For random points and normals around lamps of every kind, any light sample that arrives above
  // the receiving plane with radiance comes from a light of positive importance there: light
  // selection never leaves out light the image needs.
  SpotLamp spot;
  spot.position = glm::dvec3(0.2, -0.3, 1.0);
  spot.direction = glm::normalize(glm::dvec3(0.1, 0.2, -1.0));
  spot.spot_angle = 0.6;
  SpotLamp soft_spot = spot;
  soft_spot.radius = 0.3;
  PointLamp soft_point{glm::dvec3(-0.5, 0.4, 0.3), 20.0, glm::dvec3(1.0), 0.4};
  RectLamp tilted = rect_at(0.3);
  tilted.light_to_world = glm::dmat4(glm::dvec4(glm::normalize(glm::dvec3(1, 0, 1)), 0), glm::dvec4(0, 1, 0, 0),
                                     glm::dvec4(glm::normalize(glm::dvec3(-1, 0, 1)), 0), glm::dvec4(0.3, 0, 0.5, 1));
  tilted.size_x = 2.0;
  SunLamp sun;
  sun.direction = glm::normalize(glm::dvec3(0.3, 0.1, -1.0));
  sun.angle = 0.4;
  const std::vector<Lamp> lights = {tilted, soft_point, soft_spot, spot, sun};
  const LightSampler sampler(lights, UniformBackground(glm::vec3(0.0f)));
  UniformFloats rng(17);
  int lit = 0;
  for (int n = 0; n < 20000; ++n) {
    const glm::vec3 p = 2.0f * glm::vec3(rng.next(), rng.next(), rng.next()) - glm::vec3(1.0f);
    const ReceivingDirections receiving{random_unit_vector(rng), n % 5 == 0};
    for (size_t i = 0; i < sampler.sampled_count(); ++i)
      with_light(sampler.light(i), [&](const auto& light) {
        const auto s = light.sample(p, receiving, glm::vec2(rng.next(), rng.next()));
        if (!s || !(s->radiance.x + s->radiance.y + s->radiance.z > 0.0f)) return;
        if (!receiving.every_direction && !(glm::dot(s->wi, receiving.normal) > 0.0f)) return;
        ++lit;
        INFO("light " << i << " at (" << p.x << ", " << p.y << ", " << p.z << ")");
        CHECK(light.importance(p, receiving) > 0.0f);
      });
  }
  CHECK(lit > 10000);
}

TEST_CASE("The rectangles' weights, taken all at once, are each lamp's importance", "[render]") {
  // Nine rectangles of random pose and size (the vectorised batch runs two blocks of four and a
  // remainder) and a point lamp; sites all around them, inside their bounding spheres and behind
  // them, with reflecting and transmitting BSDFs.
  UniformFloats rng(5);
  std::vector<Lamp> lights;
  for (int k = 0; k < 9; ++k) {
    RectLamp rect;
    const glm::dvec3 z = glm::dvec3(random_unit_vector(rng));
    const glm::dvec3 x = glm::normalize(glm::cross(z, std::abs(z.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
    rect.light_to_world = glm::dmat4(glm::dvec4(x, 0), glm::dvec4(glm::cross(z, x), 0), glm::dvec4(z, 0),
                                     glm::dvec4(2.0 * glm::dvec3(rng.next(), rng.next(), rng.next()) - 1.0, 1));
    rect.size_x = 0.05 + rng.next();
    rect.size_y = 0.05 + 0.5 * rng.next();
    rect.power = 10.0 + 100.0 * rng.next();
    lights.push_back(rect);
  }
  lights.push_back(PointLamp{glm::dvec3(0.0, 0.0, 3.0), 10.0, glm::dvec3(1.0)});
  const LightSampler sampler(lights, UniformBackground(glm::vec3(0.0f)));
  REQUIRE(sampler.sampled_count() == 10);
  int zeros = 0;
  for (int n = 0; n < 2000; ++n) {
    const glm::vec3 p = 3.0f * glm::vec3(rng.next(), rng.next(), rng.next()) - glm::vec3(1.5f);
    const ReceivingDirections receiving{random_unit_vector(rng), n % 3 == 0};
    const PickSite site = sampler.site(p, receiving);
    double total = 0.0;
    for (size_t i = 0; i < sampler.sampled_count(); ++i) {
      const float one = with_light(sampler.light(i), [&](const auto& light) { return light.importance(p, receiving); });
      // Bit for bit in the default build; -march=native may fuse multiply-adds differently in
      // the two loops.
      CHECK(site.weights[i] == Approx(one).epsilon(1e-6).margin(0.0));
      CHECK((site.weights[i] > 0.0f) == (one > 0.0f));
      zeros += one == 0.0f;
      total += one;
    }
    CHECK(site.total_importance == Approx(total).epsilon(1e-5));
  }
  CHECK(zeros > 1000);  // the sites behind lamps and below receiving planes were met
}

TEST_CASE("Without lamps nothing is drawn, and a black background is no light", "[render]") {
  const LightSampler dark({}, UniformBackground(glm::vec3(0.0f)));
  float u = 0.5f;
  const PickSite site = dark.site(glm::vec3(0.0f), {});
  CHECK(dark.empty());
  CHECK_FALSE(dark.pick(site, &u));
  CHECK_FALSE(dark.sample(site, glm::vec2(0.5f)));
  CHECK(dark.escaped_radiance(glm::vec3(0, 0, 1), ScatteredRay{1.0f, false, false, &site}) == glm::vec3(0.0f));
  CHECK_FALSE(dark.has_area_lights());
}

TEST_CASE("A ray leaving the scene sees the uniform background with MIS weight 1", "[render]") {
  // The background is never drawn by light sampling, so BSDF sampling is its only strategy.
  const glm::vec3 background(0.1f, 0.2f, 0.3f);
  const LightSampler sampler({rect_at(0.0)}, UniformBackground(background));
  const PickSite site = sampler.site(glm::vec3(0.0f), {});
  for (float bsdf_pdf : {0.0f, 1e-30f, 0.3f, 1e30f})
    for (bool specular : {false, true})
      CHECK(sampler.escaped_radiance(glm::normalize(glm::vec3(0.3f, -0.2f, 0.9f)),
                                     ScatteredRay{bsdf_pdf, specular, false, &site}) == background);
}

TEST_CASE("A light sample's pdf includes the probability of picking the light", "[render]") {
  const LightSampler sampler({PointLamp{glm::dvec3(0.0, 0.0, 2.0), 10.0, glm::dvec3(1.0)}, PointLamp{}},
                             UniformBackground(glm::vec3(0.0f)), LightSelection::Uniform);
  const auto s = sampler.sample(sampler.site(glm::vec3(0.0f, 0.0f, 1.0f), {}), glm::vec2(0.25f, 0.5f));
  REQUIRE(s);
  CHECK(s->delta);
  CHECK(s->pdf == 0.5f);
  CHECK(s->wi == glm::vec3(0.0f, 0.0f, 1.0f));
  CHECK(s->distance == 1.0f);
}

TEST_CASE("Every light a ray finds is weighed by one MIS rule", "[render]") {
  const LightSampler sampler({rect_at(0.0), PointLamp{glm::dvec3(0.0, 0.0, 2.0), 10.0, glm::dvec3(1.0)}},
                             UniformBackground(glm::vec3(0.5f)));
  const PickSite site = sampler.site(glm::vec3(0.0f), {glm::vec3(0.0f, 0.0f, 1.0f), false});
  int pdf_calls = 0;
  auto light_pdf = [&pdf_calls] {
    ++pdf_calls;
    return 2.0f;
  };
  // No light sample competes with the camera's ray or a specular bounce: weight 1, no density asked.
  CHECK(sampler.found_light_weight(0, ScatteredRay{0.7f, false, true, &site}, light_pdf) == 1.0f);
  CHECK(sampler.found_light_weight(0, ScatteredRay{0.7f, true, false, &site}, light_pdf) == 1.0f);
  CHECK(pdf_calls == 0);
  // Otherwise the power heuristic against the pick's probability times the light's density.
  const float light_density = sampler.pick_probability(0, site) * 2.0f;
  CHECK(sampler.found_light_weight(0, ScatteredRay{0.7f, false, false, &site}, light_pdf) ==
        Approx(0.49f / (0.49f + light_density * light_density)));
  // A uniform background is outside light sampling's distribution: BSDF sampling alone finds it.
  REQUIRE(sampler.sampled_count() == 2);
  CHECK(sampler.found_light_weight(2, ScatteredRay{0.7f, false, false, &site}, light_pdf) == 1.0f);
}
