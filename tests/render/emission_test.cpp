// Emission (the Principled BSDF's Emission x Emission Strength) against closed forms: what the
// camera sees of an emitting surface, from either side, and the radiance inside a closed box
// that emits and reflects everywhere, L = E / (1 - a), the geometric series of bounces.
#include <catch2/catch.hpp>

#include <cmath>

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
