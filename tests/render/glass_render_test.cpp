// Glass in whole renders: a closed smooth glass object of base colour 1 in a white furnace passes
// all light on (every interface reflects F and refracts 1 - F), a rough one loses some and never
// gains, and glass in hard configurations (grazing views, total internal reflection, nested and
// touching surfaces, a thin pane) gives finite pixels.
#include <catch2/catch.hpp>

#include <cmath>

#include "matrender/camera.h"
#include "matrender/render.h"
#include "matrender/scene.h"
#include "test_scenes.h"

using namespace matrender;

namespace {

Material glass(float roughness, float ior = 1.5f) {
  Material m;
  m.set(MaterialParameter::BaseColor, glm::vec3(1.0f));
  m.set(MaterialParameter::Roughness, roughness);
  m.set(MaterialParameter::Transmission, 1.0f);
  m.set(MaterialParameter::Ior, ior);
  return m;
}

// A closed box of half-sizes h around c, 12 triangles wound outward.
matgeom::TriangleMesh closed_box(const glm::vec3& h, const glm::vec3& c = glm::vec3(0.0f)) {
  matgeom::TriangleMesh m;
  for (int corner = 0; corner < 8; ++corner)
    m.positions.push_back(c + glm::vec3(corner & 1 ? h.x : -h.x, corner & 2 ? h.y : -h.y, corner & 4 ? h.z : -h.z));
  m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                 {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return m;
}

// Bounce limits high enough that no path of these scenes ends for want of bounces.
RenderSettings furnace_settings(int spp) {
  RenderSettings settings;
  settings.samples_per_pixel = spp;
  settings.max_bounces = settings.max_glossy_bounces = settings.max_transmission_bounces = 256;
  settings.aovs = 0;
  return settings;
}

FrameBuffers render_in_furnace(const matgeom::TriangleMesh& mesh, const Material& material, int spp) {
  Scene scene;
  scene.add_mesh(mesh, {scene.add_material(material)});
  scene.set_background(glm::vec3(1.0f));
  FrameBuffers frame;
  render(scene, Camera::look_at({0.0, -3.0, 0.4}, {0.0, 0.0, 0.0}, {0, 0, 1}, 0.5, 24, 24), furnace_settings(spp),
         frame);
  return frame;
}

}  // namespace

TEST_CASE("A closed smooth glass object in a white furnace shows exactly 1", "[render]") {
  // Every bounce keeps the throughput at 1: the reflection is picked with probability F and weighs
  // F / F, the refraction 1 - F over 1 - F. Only the refraction's floor of 1e-4 (Cycles') adds
  // up to 1e-4 at grazing incidence.
  for (const float ior : {1.33f, 1.5f, 2.4f}) {
    for (const bool box : {false, true}) {
      CAPTURE(ior, box);
      // A sphere (no total internal reflection can trap a path in it) and a thin closed pane,
      // 0.02 m thick, seen nearly edge-on.
      const matgeom::TriangleMesh mesh = box ? closed_box({0.6f, 0.01f, 0.6f}) : test_scenes::uv_sphere(0.5, 32);
      const FrameBuffers frame = render_in_furnace(mesh, glass(0.0f, ior), 4);
      for (float v : frame.color) {
        INFO("pixel value " << v);
        CHECK(std::abs(v - 1.0f) <= 2e-4f);
      }
    }
  }
}

TEST_CASE("A rough glass sphere in a white furnace loses light and never gains it", "[render]") {
  // Single-scatter GGX drops what scatters more than once between microfacets.
  const FrameBuffers frame = render_in_furnace(test_scenes::uv_sphere(0.5, 32), glass(0.5f), 64);
  const test_scenes::PixelStatistics s = test_scenes::channel_statistics(frame, 1);
  INFO("mean " << s.mean << " +- " << s.standard_error);
  CHECK(s.mean <= 1.0 + 4.0 * s.standard_error);
  CHECK(s.mean < 0.999);
  CHECK(test_scenes::all_finite(frame.color));
}

TEST_CASE("Glass in hard configurations gives finite pixels", "[render]") {
  // Nested spheres (glass in glass, different indices), a sphere touching a box face, a box
  // inside a box sharing a face (coincident surfaces), a diamond-like index with much total
  // internal reflection, a lamp inside the glass, grazing views; smooth and rough.
  for (const float roughness : {0.0f, 0.02f, 0.5f, 1.0f}) {
    Scene scene;
    const uint32_t outer = scene.add_material(glass(roughness, 1.5f));
    const uint32_t inner = scene.add_material(glass(roughness, 2.4f));
    scene.add_mesh(test_scenes::uv_sphere(0.5, 24), {outer});
    scene.add_mesh(test_scenes::uv_sphere(0.25, 16), {inner});
    scene.add_mesh(closed_box({0.3f, 0.3f, 0.3f}, {0.8f, 0.0f, 0.0f}), {inner});
    scene.add_mesh(closed_box({0.3f, 0.3f, 0.1f}, {0.8f, 0.0f, 0.2f}), {outer});
    scene.add_mesh(test_scenes::horizontal_square(6.0, -0.5), {scene.add_material(test_scenes::lambert(0.5f))});
    scene.add_lamp(PointLamp{glm::dvec3(0.0, 0.0, 0.1), 10.0, glm::dvec3(1.0)});
    RectLamp lamp;
    lamp.light_to_world[3] = glm::dvec4(0.0, 0.0, 2.0, 1.0);
    lamp.size_x = lamp.size_y = 1.0;
    lamp.power = 100.0;
    scene.add_lamp(lamp);
    scene.set_background(glm::vec3(0.3f));
    RenderSettings settings;
    settings.samples_per_pixel = 8;
    for (const glm::dvec3 eye : {glm::dvec3(0.3, -3.0, 0.2), glm::dvec3(3.0, 0.2, -0.49)}) {
      FrameBuffers frame;
      const RenderStats stats = render(scene, Camera::look_at(eye, {0.3, 0.0, 0.0}, {0, 0, 1}, 0.9, 24, 24),
                                       settings, frame);
      CAPTURE(roughness, eye.x);
      CHECK(test_scenes::all_finite(frame.color));
      CHECK(stats.discarded_samples == 0);
    }
  }
}

TEST_CASE("The transmission bounce limit ends paths at the next surface, as Cycles'", "[render]") {
  // Looking at the centre of a smooth glass sphere in a white furnace, nearly head-on. With no
  // transmission bounce allowed the refracted ray ends where it meets the back of the sphere:
  // only the front reflection, F(1) = ((1.5 - 1) / (1.5 + 1))^2 = 0.04, remains. With one, the
  // ray reaches the back (and whatever it reflects inside reaches the front) with one
  // transmission counted; the second takes it out of the sphere, and a ray that leaves is not
  // checked again: everything arrives.
  Scene scene;
  scene.add_mesh(test_scenes::uv_sphere(0.5, 64), {scene.add_material(glass(0.0f))});
  scene.set_background(glm::vec3(1.0f));
  for (const int limit : {0, 1}) {
    RenderSettings settings = furnace_settings(16);
    settings.max_transmission_bounces = limit;
    FrameBuffers frame;
    render(scene, Camera::look_at({0.0, -3.0, 0.0}, {0.0, 0.0, 0.0}, {0, 0, 1}, 0.01, 8, 8), settings, frame);
    const double expected = limit == 0 ? 0.04 : 1.0;
    const test_scenes::PixelStatistics s = test_scenes::channel_statistics(frame, 0);
    CAPTURE(limit, s.mean, expected);
    // Within the view's 0.3 degrees F changes by less than 1e-6.
    CHECK(std::abs(s.mean - expected) <= 4.0 * s.standard_error + 1e-4);
  }
}
