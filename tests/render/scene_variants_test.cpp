// One scene, many variants: switching which material each part uses, or the lamps, after the BVH
// is built renders exactly what a scene built from scratch with that choice renders.
#include <catch2/catch.hpp>

#include <array>
#include <stdexcept>
#include <vector>

#include "matrender/camera.h"
#include "matrender/render.h"
#include "matrender/scene.h"
#include "test_scenes.h"

using namespace matrender;

namespace {

// Two unit squares side by side, parts 0 and 1, with UVs (so a normal map can apply).
matgeom::TriangleMesh two_part_floor() {
  matgeom::TriangleMesh left = test_scenes::horizontal_square(1.0);
  matgeom::TriangleMesh mesh = left;
  for (glm::vec3& p : mesh.positions) p.x -= 0.5f;
  for (glm::vec3 p : left.positions) mesh.positions.push_back(p + glm::vec3(0.5f, 0.0f, 0.0f));
  mesh.uvs.insert(mesh.uvs.end(), left.uvs.begin(), left.uvs.end());
  for (const glm::uvec3& t : left.triangles) mesh.triangles.push_back(t + glm::uvec3(4));
  mesh.triangle_parts = {0, 0, 1, 1};
  return mesh;
}

std::vector<Material> variant_materials() {
  Material red, metal, bumpy;
  red.set(MaterialParameter::BaseColor, glm::vec3(0.8f, 0.1f, 0.1f));
  metal.set(MaterialParameter::Metallic, 1.0f).set(MaterialParameter::Roughness, 0.2f);
  // A tilted normal everywhere: only right if the mesh got tangents for it.
  const std::array<float, 3> tilted = {0.75f, 0.5f, 0.9f};
  bumpy.normal_map = Texture::from_pixelsf(1, 1, 3, tilted.data(), ColorSpace::NonColor);
  return {red, metal, bumpy};
}

Scene scene_with(const std::vector<uint32_t>& parts, const Lamp& light) {
  Scene scene;
  for (const Material& m : variant_materials()) scene.add_material(m);
  scene.add_mesh(two_part_floor(), parts);
  scene.add_lamp(light);
  return scene;
}

std::vector<float> render_color(Scene& scene) {
  RenderSettings settings;
  settings.samples_per_pixel = 16;
  settings.seed = 5;
  settings.aovs = 0;
  FrameBuffers frame;
  render(scene, Camera::look_at({0.3, -1.2, 1.0}, {0, 0, 0}, {0, 0, 1}, 1.0, 32, 24), settings, frame);
  return frame.color;
}

const Lamp kOverhead = PointLamp{glm::dvec3(0.2, 0.1, 1.0), 40.0, glm::dvec3(1.0)};
const Lamp kSpot = SpotLamp{glm::dvec3(-0.5, -0.5, 0.8), glm::dvec3(0.5, 0.5, -0.8), 1.0, 0.2, 60.0, glm::dvec3(1.0)};

}  // namespace

TEST_CASE("Switching part materials after the BVH is built renders as a scene built that way", "[render]") {
  Scene scene = scene_with({0, 1}, kOverhead);
  const std::vector<float> first = render_color(scene);
  const double build_seconds = scene.bvh_build_seconds();
  for (const std::vector<uint32_t>& parts : {std::vector<uint32_t>{1, 0}, {2, 2}, {0, 2}}) {
    scene.set_part_materials(0, parts);
    CHECK(scene.part_materials(0) == parts);
    Scene fresh = scene_with(parts, kOverhead);
    const std::vector<float> switched = render_color(scene);
    CHECK(switched == render_color(fresh));
    CHECK(switched != first);
    CHECK(test_scenes::all_finite(switched));
  }
  CHECK(scene.committed());
  CHECK(scene.bvh_build_seconds() == build_seconds);  // built once
}

TEST_CASE("Switching the lamps after the BVH is built renders as a scene built that way", "[render]") {
  Scene scene = scene_with({0, 1}, kOverhead);
  render_color(scene);
  scene.clear_lamps();
  scene.add_lamp(kSpot);
  Scene fresh = scene_with({0, 1}, kSpot);
  CHECK(render_color(scene) == render_color(fresh));
}

TEST_CASE("Part materials must name a mesh, existing materials and every part", "[render]") {
  Scene scene = scene_with({0, 1}, kOverhead);
  CHECK_THROWS_AS(scene.set_part_materials(1, {0, 0}), std::invalid_argument);
  CHECK_THROWS_AS(scene.set_part_materials(0, {0, 3}), std::invalid_argument);
  CHECK_THROWS_AS(scene.set_part_materials(0, {0}), std::invalid_argument);
  CHECK(scene.part_materials(0) == std::vector<uint32_t>{0, 1});
}
