// Meshes moved, hidden and shown after the BVH is built: where a mesh is depends only on its last
// transform (never on the moves before), a hidden mesh neither occludes nor casts a shadow, and
// the scene renders as if it had been built that way.
#include <catch2/catch.hpp>

#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "matrender/render.h"
#include "matrender/scene_builder.h"
#include "matrender/scene_file.h"

using namespace matrender;

namespace {

// A vase and a mug on a floor under the rig, seen from the side.
BuiltScene vase_and_mug(const std::string& mug_transform = "") {
  return build_scene(read_scene_text(R"({
    "camera": {"position": [0.9, -0.9, 0.5], "look_at": [0, 0, 0.15], "width": 40, "height": 40},
    "lights": {"rig": {}},
    "objects": [{"builtin": "vase"},
                {"builtin": "mug", "surroundings": true)" + mug_transform + R"(},
                {"room": {"floor_center": [0, 0, 0], "half_width": 5}}]})",
                                     "moves test", "."));
}

FrameBuffers rendered(BuiltScene& built) {
  RenderSettings settings;
  settings.samples_per_pixel = 4;
  settings.seed = 7;
  settings.aovs = AovObjectId;
  FrameBuffers frame;
  render(built.scene, built.camera, settings, frame);
  return frame;
}

const glm::dmat4 kAside = glm::translate(glm::dmat4(1.0), glm::dvec3(0.22, 0.22, 0.0));

}  // namespace

TEST_CASE("A moved mesh renders exactly as one built in its place, whatever moves came before", "[render]") {
  BuiltScene built_there = vase_and_mug(R"(, "transform": {"translate": [0.22, 0.22, 0]})");
  const FrameBuffers reference = rendered(built_there);

  BuiltScene moved = vase_and_mug();
  const uint32_t mug = moved.object_meshes[1];
  const FrameBuffers before = rendered(moved);
  CHECK(before.color != reference.color);
  moved.scene.set_mesh_transform(mug, glm::rotate(glm::dmat4(1.0), 1.0, glm::dvec3(0, 0, 1)) * glm::dmat4(2.0));
  rendered(moved);
  moved.scene.set_mesh_transform(mug, kAside);
  const FrameBuffers after = rendered(moved);
  CHECK(after.color == reference.color);
  CHECK(after.object_id == reference.object_id);
  // Back where it was added: the first image again.
  moved.scene.set_mesh_transform(mug, glm::dmat4(1.0));
  CHECK(rendered(moved).color == before.color);
}

TEST_CASE("A hidden mesh is seen by no ray and shadows nothing; shown again, the image is as before", "[render]") {
  BuiltScene built = vase_and_mug(R"(, "transform": {"translate": [0.22, 0.22, 0]})");
  const uint32_t mug = built.object_meshes[1];
  const FrameBuffers shown = rendered(built);
  size_t mug_pixels = 0;
  for (const int32_t id : shown.object_id) mug_pixels += id == static_cast<int32_t>(mug);
  REQUIRE(mug_pixels > 10);

  built.scene.set_mesh_enabled(mug, false);
  CHECK_FALSE(built.scene.mesh_enabled(mug));
  const FrameBuffers hidden = rendered(built);
  for (const int32_t id : hidden.object_id) CHECK(id != static_cast<int32_t>(mug));
  // The scene without the mug, built so.
  BuiltScene without = build_scene(read_scene_text(R"({
    "camera": {"position": [0.9, -0.9, 0.5], "look_at": [0, 0, 0.15], "width": 40, "height": 40},
    "lights": {"rig": {}},
    "objects": [{"builtin": "vase"}, {"room": {"floor_center": [0, 0, 0], "half_width": 5}}]})",
                                                   "moves test", "."));
  const FrameBuffers reference = rendered(without);
  CHECK(hidden.color == reference.color);

  built.scene.set_mesh_enabled(mug, true);
  CHECK(rendered(built).color == shown.color);
}

TEST_CASE("Moves that cannot be rendered are refused", "[render]") {
  BuiltScene built = vase_and_mug();
  CHECK_THROWS_AS(built.scene.set_mesh_transform(7, glm::dmat4(1.0)), std::invalid_argument);
  CHECK_THROWS_AS(built.scene.set_mesh_transform(1, glm::dmat4(0.0)), std::invalid_argument);
  glm::dmat4 far = glm::dmat4(1.0);
  far[3][0] = 1e12;
  CHECK_THROWS_AS(built.scene.set_mesh_transform(1, far), std::invalid_argument);
  glm::dmat4 nan = glm::dmat4(1.0);
  nan[3][1] = std::nan("");
  CHECK_THROWS_AS(built.scene.set_mesh_transform(1, nan), std::invalid_argument);
  CHECK_THROWS_AS(built.scene.set_mesh_enabled(9, false), std::invalid_argument);
}
