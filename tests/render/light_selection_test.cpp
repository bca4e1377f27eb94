// Importance and uniform light selection render the same image: a room whose back wall 10 lamps
// light from in front of it, with 4 more lamps on a sphere, a soft point lamp and a sun, rendered
// both ways. Pixels are independent, so the mean of the per-pixel differences has a standard
// error from their spread; it must be within four of them of 0, overall and on each third of the
// image.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "matgeom/camera_grid.h"
#include "matrender/camera.h"
#include "matrender/render.h"
#include "matrender/scene.h"
#include "test_scenes.h"

using namespace matrender;

namespace {

RectLamp lamp_facing(const glm::dvec3& position, const glm::dvec3& target, double size, double power) {
  RectLamp lamp;
  lamp.light_to_world = matgeom::look_at_camera_to_world(position, target, {0, 0, 1});
  lamp.size_x = lamp.size_y = size;
  lamp.power = power;
  return lamp;
}

Scene back_lit_room() {
  Scene scene;
  const uint32_t grey = scene.add_material(test_scenes::lambert(0.7f));
  scene.add_mesh(test_scenes::horizontal_square(8.0), {grey});
  matgeom::TriangleMesh wall = test_scenes::horizontal_square(8.0);
  for (glm::vec3& p : wall.positions) p = glm::vec3(p.x, 2.0f, p.y + 4.0f);  // the plane y = 2, facing -y
  std::swap(wall.triangles[0].y, wall.triangles[0].z);
  std::swap(wall.triangles[1].y, wall.triangles[1].z);
  scene.add_mesh(wall, {grey});
  Material glossy;
  glossy.set(MaterialParameter::BaseColor, glm::vec3(0.6f, 0.4f, 0.3f));
  glossy.set(MaterialParameter::Roughness, 0.3f);
  scene.add_mesh(test_scenes::uv_sphere(0.3, 24, glm::dvec3(0.0, 0.0, 0.3)), {scene.add_material(glossy)});
  for (int k = 0; k < 10; ++k) {
    const double x = -1.8 + 0.4 * k;
    scene.add_lamp(lamp_facing({x, 1.7, 0.5}, {x, 2.0, 0.7}, 0.25, 30.0));
  }
  for (const glm::dvec3& at : {glm::dvec3(1.0, -1.0, 0.8), glm::dvec3(-1.0, -1.0, 0.8), glm::dvec3(0.8, 0.6, 1.2),
                               glm::dvec3(-0.8, 0.6, 1.2)})
    scene.add_lamp(lamp_facing(at, {0.0, 0.0, 0.3}, 0.4, 40.0));
  scene.add_lamp(PointLamp{glm::dvec3(0.5, -0.6, 0.4), 5.0, glm::dvec3(1.0), 0.1});
  SunLamp sun;
  sun.direction = glm::normalize(glm::dvec3(0.2, 1.0, -0.6));
  sun.strength = 0.5;
  sun.angle = 0.1;
  scene.add_lamp(sun);
  return scene;
}

std::vector<float> render_with(Scene& scene, LightSelection selection, uint32_t seed) {
  RenderSettings settings;
  settings.samples_per_pixel = 64;
  settings.seed = seed;
  settings.aovs = 0;
  settings.light_selection = selection;
  FrameBuffers frame;
  const Camera camera = Camera::look_at({0.0, -2.2, 0.9}, {0.0, 0.5, 0.5}, {0, 0, 1}, 0.9, 48, 48);
  REQUIRE(render(scene, camera, settings, frame).discarded_samples == 0);
  return frame.color;
}

}  // namespace

TEST_CASE("Importance and uniform light selection converge to the same image", "[render]") {
  Scene scene = back_lit_room();
  const std::vector<float> importance = render_with(scene, LightSelection::Importance, 1);
  const std::vector<float> uniform = render_with(scene, LightSelection::Uniform, 2);
  const size_t pixels = importance.size() / 3;
  CHECK(test_scenes::mean_of(importance) > 0.1);
  // Thirds of the image by rows: the wall the 10 lamps light, the sphere, the floor.
  for (size_t third = 0; third < 4; ++third) {
    const size_t first = third == 3 ? 0 : third * pixels / 3, last = third == 3 ? pixels : (third + 1) * pixels / 3;
    const test_scenes::PixelStatistics d = test_scenes::difference_statistics(importance, uniform, first, last);
    INFO((third == 3 ? "whole image" : "third " + std::to_string(third)) << ": mean difference " << d.mean << " +- "
                                                                          << d.standard_error);
    CHECK(std::abs(d.mean) <= 4.0 * d.standard_error);
  }
}
