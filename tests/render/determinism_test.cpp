// The image for a seed does not depend on the thread count; the seed changes the noise.
#include <catch2/catch.hpp>

#include <cstring>

#include "matrender/camera.h"
#include "matrender/render.h"
#include "matrender/scene.h"
#include "matrender/texture.h"
#include "test_scenes.h"

using namespace matrender;

namespace {

// `white`, when given, multiplies every material input that can be textured.
Scene glossy_box_scene(const TexturePtr& white = nullptr) {
  const auto texture = [&](Material m) {
    m[matrender::MaterialParameter::BaseColor].texture = m[matrender::MaterialParameter::Roughness].texture = m[matrender::MaterialParameter::Metallic].texture = white;
    return m;
  };
  Scene scene;
  Material floor = test_scenes::lambert(0.7f);
  floor.diffuse_model = DiffuseModel::Principled;
  floor.set(matrender::MaterialParameter::Specular, 0.5f);
  floor.set(matrender::MaterialParameter::Roughness, 0.3f);
  matgeom::TriangleMesh mesh = test_scenes::horizontal_square(4.0);
  scene.add_mesh(mesh, {scene.add_material(texture(floor))});
  Material metal;
  metal.set(matrender::MaterialParameter::BaseColor, glm::vec3(0.9f, 0.6f, 0.3f));
  metal.set(matrender::MaterialParameter::Metallic, 1.0f);
  metal.set(matrender::MaterialParameter::Roughness, 0.2f);
  scene.add_mesh(test_scenes::horizontal_square(0.5, 0.4), {scene.add_material(texture(metal))});
  RectLamp lamp;
  lamp.light_to_world[3] = glm::dvec4(0.0, 0.0, 2.0, 1.0);
  lamp.power = 200.0;
  scene.add_lamp(lamp);
  scene.add_lamp(PointLamp{glm::dvec3(1.0, 1.0, 1.0), 50.0, glm::dvec3(1.0)});
  scene.set_background(glm::vec3(0.05f));
  return scene;
}

}  // namespace

TEST_CASE("One and two threads give bit-identical images for the same seed", "[render]") {
  Scene scene = glossy_box_scene();
  const Camera camera = Camera::look_at({2.0, -2.0, 1.5}, {0, 0, 0.2}, {0, 0, 1}, 0.7, 48, 40);
  RenderSettings settings;
  settings.samples_per_pixel = 16;
  settings.seed = 3;
  FrameBuffers one, two, other_seed;
  settings.threads = 1;
  render(scene, camera, settings, one);
  settings.threads = 2;
  render(scene, camera, settings, two);
  REQUIRE(one.color.size() == two.color.size());
  CHECK(std::memcmp(one.color.data(), two.color.data(), one.color.size() * sizeof(float)) == 0);
  CHECK(std::memcmp(one.normal_world.data(), two.normal_world.data(), one.normal_world.size() * sizeof(float)) == 0);
  CHECK(one.label == two.label);
  CHECK(one.depth == two.depth);

  settings.seed = 4;
  render(scene, camera, settings, other_seed);
  CHECK(std::memcmp(one.color.data(), other_seed.color.data(), one.color.size() * sizeof(float)) != 0);
}

// Untextured materials get their BSDF lobes computed once per material instead of at every hit;
// through white textures the same material takes the per-hit path and must give the same image.
TEST_CASE("A constant material renders as the same material through white textures", "[render]") {
  const float white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  const TexturePtr white_texture = Texture::from_pixelsf(1, 1, 4, white, ColorSpace::NonColor);
  const Camera camera = Camera::look_at({2.0, -2.0, 1.5}, {0, 0, 0.2}, {0, 0, 1}, 0.7, 32, 24);
  RenderSettings settings;
  settings.samples_per_pixel = 8;
  settings.threads = 1;
  FrameBuffers constant, textured;
  Scene constant_scene = glossy_box_scene();
  render(constant_scene, camera, settings, constant);
  Scene textured_scene = glossy_box_scene(white_texture);
  render(textured_scene, camera, settings, textured);
  REQUIRE(constant.color.size() == textured.color.size());
  CHECK(test_scenes::all_finite(constant.color));
  CHECK(std::memcmp(constant.color.data(), textured.color.data(), constant.color.size() * sizeof(float)) == 0);
}
