// Emission (the Principled BSDF's Emission x Emission Strength) against closed forms: what the
// camera sees of an emitting surface, from either side, and the radiance inside a closed box
// that emits and reflects everywhere, L = E / (1 - a), the geometric series of bounces.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "matbase/pi.h"
#include "matrender/camera.h"
#include "matrender/render.h"
#include "matrender/scene.h"
#include "test_scenes.h"

using namespace matrender;

namespace {

// A closed cube of half-size h around the origin, 12 triangles.
matgeom::TriangleMesh closed_cube(float h) {
  matgeom::TriangleMesh m;
  for (int corner = 0; corner < 8; ++corner)
    m.positions.push_back({corner & 1 ? h : -h, corner & 2 ? h : -h, corner & 4 ? h : -h});
  m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                 {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return m;
}

Material emitter(float albedo, const glm::vec3& emission, float strength) {
  Material m = test_scenes::lambert(albedo);
  m.set(MaterialParameter::Emission, emission);
  m.set(MaterialParameter::EmissionStrength, strength);
  return m;
}

}  // namespace

TEST_CASE("The camera sees emission times strength, from both sides", "[render]") {
  // Albedo 0: nothing but the emission reaches the camera, so every sample carries it exactly.
  const glm::vec3 emission(0.2f, 0.5f, 0.9f);
  const float strength = 3.0f;
  Scene scene;
  scene.add_mesh(test_scenes::horizontal_square(10.0), {scene.add_material(emitter(0.0f, emission, strength))});
  RenderSettings settings;
  settings.samples_per_pixel = 4;
  for (double side : {1.0, -1.0}) {
    CAPTURE(side);
    const Camera camera = Camera::look_at({0.3, 0.2, 2.0 * side}, {0.0, 0.0, 0.0}, {0, 1, 0}, 0.5, 8, 8);
    FrameBuffers frame;
    render(scene, camera, settings, frame);
    for (size_t i = 0; i < frame.color.size(); ++i)
      CHECK(frame.color[i] == Approx(emission[static_cast<int>(i % 3)] * strength).epsilon(1e-5));
  }
}

TEST_CASE("Inside a closed emitting box of albedo a the radiance is E / (1 - a)", "[render]") {
  // Every bounce adds E a^k (the Lambert sample weight is the albedo exactly); Russian roulette
  // keeps the sum unbiased and is the only noise. Bounce limits far beyond a^k's reach.
  const float albedo = 0.5f;
  const glm::vec3 emission(0.3f, 0.1f, 0.6f);
  Scene scene;
  scene.add_mesh(closed_cube(1.0f), {scene.add_material(emitter(albedo, emission, 1.0f))});
  const Camera camera = Camera::look_at({0.1, -0.2, 0.0}, {0.5, 0.7, 0.2}, {0, 0, 1}, 1.2, 24, 24);
  RenderSettings settings;
  settings.samples_per_pixel = 64;
  settings.max_bounces = settings.max_diffuse_bounces = 1000;
  FrameBuffers frame;
  render(scene, camera, settings, frame);
  for (int c = 0; c < 3; ++c) {
    const test_scenes::PixelStatistics s = test_scenes::channel_statistics(frame, c);
    const double expected = emission[c] / (1.0 - albedo);
    INFO("channel " << c << ": " << s.mean << " +- " << s.standard_error << ", expected " << expected);
    CHECK(std::abs(s.mean - expected) <= 4.0 * s.standard_error + 1e-6);
  }
  CHECK(test_scenes::all_finite(frame.color));
}

namespace {

// Irradiance at the origin (normal +Z) from a horizontal a x b rectangle of radiance L centred
// at height h above it (Lambert's polygon formula, as light_closed_form_test.cpp).
double rectangle_irradiance_below(double a, double b, double h, double radiance) {
  const std::vector<glm::dvec3> corners = {{-a / 2, -b / 2, h}, {a / 2, -b / 2, h}, {a / 2, b / 2, h}, {-a / 2, b / 2, h}};
  double sum = 0.0;
  for (size_t i = 0; i < corners.size(); ++i) {
    const glm::dvec3 u = glm::normalize(corners[i]), v = glm::normalize(corners[(i + 1) % corners.size()]);
    sum += std::acos(glm::clamp(glm::dot(u, v), -1.0, 1.0)) * glm::normalize(glm::cross(u, v)).z;
  }
  return 0.5 * radiance * std::abs(sum);
}

// A quad of emission `radiance` (albedo 0) 0.6 x 0.4 m at height 1.5 over a large plane.
void add_emissive_quad(Scene& scene, float radiance) {
  matgeom::TriangleMesh quad = test_scenes::horizontal_square(1.0, 1.5);
  for (glm::vec3& p : quad.positions) p *= glm::vec3(0.6f, 0.4f, 1.0f);
  scene.add_mesh(quad, {scene.add_material(emitter(0.0f, glm::vec3(1.0f), radiance))});
}

}  // namespace

TEST_CASE("Next-event estimation reaches emissive meshes: a plane under an emitting quad gets its polygon irradiance",
          "[render]") {
  Scene scene;
  const float albedo = 0.6f;
  scene.add_mesh(test_scenes::horizontal_square(40.0), {scene.add_material(test_scenes::lambert(albedo))});
  add_emissive_quad(scene, 5.0f);
  // Looked at from below the quad, straight down at the origin.
  const Camera camera = Camera::look_at({0, 0, 1}, {0, 0, 0}, {0, 1, 0}, 0.002, 16, 16);
  RenderSettings settings;
  settings.samples_per_pixel = 16;
  settings.max_bounces = 0;  // direct light only
  FrameBuffers frame;
  REQUIRE(render(scene, camera, settings, frame).discarded_samples == 0);
  const double expected = albedo / matbase::kPi * rectangle_irradiance_below(0.6, 0.4, 1.5, 5.0);
  const auto s = test_scenes::channel_statistics(frame, 0);
  INFO(s.mean << " +- " << s.standard_error << ", expected " << expected);
  CHECK(std::abs(s.mean - expected) < 4.0 * s.standard_error + 1e-4 * expected);
  // Light sampling does nearly all the work: 16 samples leave under 1 % noise.
  CHECK(s.standard_error < 0.01 * expected);
}

TEST_CASE("An emitting quad and a rectangle lamp of the same radiance light a glossy plane alike", "[render]") {
  // The quad is sampled by area and weighed against BSDF hits on it; the lamp by solid angle
  // against hits on it: two MIS estimators of one integral, pixel by pixel.
  const auto render_plane = [](bool emissive_mesh, uint32_t seed) {
    Scene scene;
    Material glossy;
    glossy.set(MaterialParameter::BaseColor, glm::vec3(0.7f));
    glossy.set(MaterialParameter::Metallic, 1.0f);
    glossy.set(MaterialParameter::Roughness, 0.25f);
    scene.add_mesh(test_scenes::horizontal_square(40.0), {scene.add_material(glossy)});
    if (emissive_mesh) {
      add_emissive_quad(scene, 5.0f);
    } else {
      RectLamp lamp;
      // Its +Z points up, so it emits down its -Z toward the plane.
      lamp.light_to_world[3] = glm::dvec4(0.0, 0.0, 1.5, 1.0);
      lamp.size_x = 0.6;
      lamp.size_y = 0.4;
      lamp.power = 5.0 * 4.0 * 0.6 * 0.4;  // L = P / (4 a b)
      scene.add_lamp(lamp);
    }
    RenderSettings settings;
    settings.samples_per_pixel = 64;
    settings.seed = seed;
    settings.max_bounces = 0;
    settings.aovs = 0;
    FrameBuffers frame;
    const Camera camera = Camera::look_at({0.0, -1.2, 1.0}, {0.0, 0.2, 0.0}, {0, 0, 1}, 0.8, 32, 32);
    REQUIRE(render(scene, camera, settings, frame).discarded_samples == 0);
    return frame.color;
  };
  const std::vector<float> mesh = render_plane(true, 1), lamp = render_plane(false, 2);
  const test_scenes::PixelStatistics d = test_scenes::difference_statistics(mesh, lamp, 0, mesh.size() / 3);
  const double level = test_scenes::mean_of(lamp);
  INFO("mean difference " << d.mean << " +- " << d.standard_error << ", mean value " << level);
  CHECK(level > 0.01);
  CHECK(std::abs(d.mean) <= 4.0 * d.standard_error);
}
