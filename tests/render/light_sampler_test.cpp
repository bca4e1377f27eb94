// The light set: which lights next-event estimation draws and with what probability, which ones
// rays find by themselves, and what a ray that leaves the scene sees.
#include <catch2/catch.hpp>

#include <variant>
#include <vector>

#include "lights/light_sampler.h"

using namespace matrender;

namespace {

RectLight rect_at(double x) {
  RectLight lamp;
  lamp.light_to_world[3] = glm::dvec4(x, 0.0, 1.0, 1.0);
  lamp.size_x = lamp.size_y = 0.5;
  return lamp;
}

}  // namespace

TEST_CASE("The distribution holds rectangles, disks, delta lamps and suns, not the uniform background", "[render]") {
  PointLight soft_point;
  soft_point.radius = 0.1;
  SpotLight soft_spot;
  soft_spot.radius = 0.2;
  const std::vector<Light> lights = {PointLight{}, SunLight{}, rect_at(0.0), soft_spot, SpotLight{}, rect_at(2.0),
                                     soft_point};
  const LightSampler sampler(lights, UniformBackground(glm::vec3(0.1f, 0.2f, 0.3f)));
  REQUIRE(sampler.sampled_count() == 7);
  CHECK(std::holds_alternative<PreparedRectLight>(sampler.light(0)));
  CHECK(std::holds_alternative<PreparedRectLight>(sampler.light(1)));
  CHECK(std::holds_alternative<PreparedDiskLamp>(sampler.light(2)));
  CHECK(std::holds_alternative<PreparedDiskLamp>(sampler.light(3)));
  CHECK(light_type(sampler.light(3)) == LightType::Area);
  CHECK(light_type(sampler.light(4)) == LightType::DeltaPosition);
  CHECK(light_type(sampler.light(5)) == LightType::DeltaPosition);
  CHECK(std::holds_alternative<PreparedSunLight>(sampler.light(6)));
  // The background is an eighth light, outside the distribution.
  CHECK(std::holds_alternative<UniformBackground>(sampler.light(7)));
  CHECK(sampler.selection_pdf() == Approx(1.0 / 7.0));
  CHECK(sampler.has_area_lights());
}

TEST_CASE("Rays find the disks of lamps with a radius, facing their origin, within their length", "[render]") {
  PointLight soft;
  soft.position = glm::dvec3(0.0, 0.0, 1.0);
  soft.radius = 0.2;
  const LightSampler sampler({soft}, UniformBackground(glm::vec3(0.0f)));
  const auto hits = [&](glm::vec3 origin, glm::vec3 dir, float t_max) {
    std::vector<float> ts;
    sampler.for_each_area_hit(origin, glm::normalize(dir), t_max, [&](const auto&, float t) { ts.push_back(t); });
    return ts;
  };
  CHECK(hits({0, 0, 0}, {0, 0, 1}, 10.0f) == std::vector<float>{1.0f});
  // The disk turns to face the origin: from the side it is still 0.2 wide.
  CHECK(hits({3, 0, 1}, {-1, 0.06f, 0}, 10.0f).size() == 1);
  CHECK(hits({3, 0, 1}, {-1, 0.07f, 0}, 10.0f).empty());
  CHECK(hits({0, 0, 0}, {0, 0, 1}, 0.99f).empty());
  CHECK(hits({0, 0, 0}, {0, 0, -1}, 10.0f).empty());
}

TEST_CASE("A pick chooses each light of the distribution over an equal interval and rescales u", "[render]") {
  const LightSampler sampler({rect_at(0.0), PointLight{}, SpotLight{}}, UniformBackground(glm::vec3(0.0f)));
  for (int k = 0; k < 3; ++k)
    for (double within : {0.0, 0.25, 0.5, 0.75}) {
      float u = static_cast<float>((k + within) / 3.0);
      const auto picked = sampler.pick(&u);
      REQUIRE(picked);
      CHECK(picked->index == static_cast<size_t>(k));
      CHECK(picked->probability == Approx(1.0 / 3.0));
      CHECK(u == Approx(within).margin(1e-6));
    }
  float last = 0x1.fffffep-1f;
  const auto picked = sampler.pick(&last);
  REQUIRE(picked);
  CHECK(picked->index == 2);
  CHECK(last < 1.0f);
}

TEST_CASE("Without lamps nothing is drawn, and a black background is no light", "[render]") {
  const LightSampler dark({}, UniformBackground(glm::vec3(0.0f)));
  float u = 0.5f;
  CHECK(dark.empty());
  CHECK_FALSE(dark.pick(&u));
  CHECK_FALSE(dark.sample(glm::vec3(0.0f), {}, glm::vec2(0.5f)));
  CHECK(dark.escaped_radiance(glm::vec3(0, 0, 1), 1.0f, false) == glm::vec3(0.0f));
  CHECK_FALSE(dark.has_area_lights());
}

TEST_CASE("A ray leaving the scene sees the uniform background with MIS weight 1", "[render]") {
  // The background is never drawn by light sampling, so BSDF sampling is its only strategy.
  const glm::vec3 background(0.1f, 0.2f, 0.3f);
  const LightSampler sampler({rect_at(0.0)}, UniformBackground(background));
  for (float bsdf_pdf : {0.0f, 1e-30f, 0.3f, 1e30f})
    for (bool specular : {false, true})
      CHECK(sampler.escaped_radiance(glm::normalize(glm::vec3(0.3f, -0.2f, 0.9f)), bsdf_pdf, specular) == background);
}

TEST_CASE("A light sample's pdf includes the probability of picking the light", "[render]") {
  const LightSampler sampler({PointLight{glm::dvec3(0.0, 0.0, 2.0), 10.0, glm::dvec3(1.0)}, PointLight{}},
                             UniformBackground(glm::vec3(0.0f)));
  const auto s = sampler.sample(glm::vec3(0.0f, 0.0f, 1.0f), {}, glm::vec2(0.25f, 0.5f));
  REQUIRE(s);
  CHECK(s->delta);
  CHECK(s->pdf == 0.5f);
  CHECK(s->wi == glm::vec3(0.0f, 0.0f, 1.0f));
  CHECK(s->distance == 1.0f);
}
