// A room in a scene file: the object id AOV tells the object from the room pixel by pixel, the
// room does not move the rig or the grid camera (it is surroundings), and a closed box lets no
// light in from the world outside it.
#include <catch2/catch.hpp>

#include <string>

#include "matrender/render.h"
#include "matrender/scene_builder.h"
#include "matrender/scene_file.h"

using namespace matrender;

namespace {

constexpr const char* kHead = R"({"camera": {"position": [2, 1, 1], "look_at": [0, 0, 0]}, "lights": [], )";

BuiltScene built_from(const std::string& json) { return build_scene(read_scene_text(json, "room test", ".")); }

}  // namespace

TEST_CASE("The object id of a pixel is the object its nearest hit is on: the vase, the floor, or nothing", "[render]") {
  const std::string scene = R"({
    "camera": {"grid": {"n_phi": 4, "n_theta": 4, "cell": [3, 0], "radius": 1.2}, "width": 48, "height": 48},
    "lights": {"rig": {}},
    "objects": [{"builtin": "vase"},
                {"room": {"floor_center": [0, 0, 0], "half_width": 30}}],
    "render": {"spp": 4, "seed": 1}})";
  BuiltScene built = built_from(scene);
  BuiltScene alone = built_from(R"({
    "camera": {"grid": {"n_phi": 4, "n_theta": 4, "cell": [3, 0], "radius": 1.2}, "width": 48, "height": 48},
    "lights": {"rig": {}},
    "objects": [{"builtin": "vase"}]})");
  // The floor is surroundings: the bounds and the grid's centre are the vase's alone.
  CHECK(built.bounds.radius == alone.bounds.radius);
  CHECK(built.centroid == alone.centroid);
  CHECK(built.object_meshes.size() == 2);

  RenderSettings settings;
  settings.samples_per_pixel = 4;
  settings.aovs = AovObjectId | AovLabel | AovAlpha;
  FrameBuffers frame;
  render(built.scene, built.camera, settings, frame);
  REQUIRE(frame.object_id.size() == 48u * 48u);
  size_t vase = 0, floor = 0, sky = 0;
  for (const int32_t id : frame.object_id) {
    vase += id == static_cast<int32_t>(built.object_meshes[0]);
    floor += id == static_cast<int32_t>(built.object_meshes[1]);
    sky += id == -1;
  }
  CHECK(vase + floor + sky == frame.object_id.size());
  CHECK(vase > 100);
  CHECK(floor > 100);  // a camera low on the grid sees the floor to the horizon
  CHECK(sky > 20);     // and the empty world above it
  // The centre pixel is the vase's; the bottom row the floor's.
  CHECK(frame.object_id[24 * 48 + 24] == static_cast<int32_t>(built.object_meshes[0]));
  for (int x = 0; x < 48; ++x) CHECK(frame.object_id[47 * 48 + x] == static_cast<int32_t>(built.object_meshes[1]));
  // Object id and alpha agree on the background.
  for (size_t p = 0; p < frame.object_id.size(); ++p)
    if (frame.object_id[p] == -1) CHECK(frame.alpha[p] < 1.0f);
}

TEST_CASE("A closed box room lets no light in from a bright world outside", "[render]") {
  // The camera and the vase inside the room, no lamp: every pixel exactly 0.
  const std::string scene = R"({
    "camera": {"position": [0.9, -0.7, 0.6], "look_at": [0, 0, 0.2], "width": 32, "height": 32},
    "lights": [],
    "background": [5, 5, 5],
    "objects": [{"builtin": "vase"},
                {"room": {"floor_center": [0, 0, 0], "half_width": 1.5, "height": 1.8, "walls": "box", "ceiling": true}}],
    "render": {"spp": 16, "seed": 3, "max_bounces": 8}})";
  BuiltScene built = built_from(scene);
  RenderSettings settings;
  settings.samples_per_pixel = 16;
  settings.max_bounces = 8;
  FrameBuffers frame;
  render(built.scene, built.camera, settings, frame);
  double brightest = 0.0;
  for (const float v : frame.color) brightest = std::max(brightest, static_cast<double>(v));
  CHECK(brightest == 0.0);
  // The same room without its ceiling is lit from above.
  BuiltScene open = built_from(std::string(scene).replace(scene.find("\"ceiling\": true"), 15, "\"ceiling\": false"));
  FrameBuffers lit;
  render(open.scene, open.camera, settings, lit);
  double sum = 0.0;
  for (const float v : lit.color) sum += v;
  CHECK(sum > 0.0);
}

TEST_CASE("A scene file's room is checked where it is read", "[render]") {
  const auto refusal = [](const std::string& room) {
    try {
      read_scene_text(std::string(kHead) + R"("objects": [{"builtin": "vase"}, {"room": )" + room + "}]}", "scene.json",
                      ".");
    } catch (const matbase::InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  CHECK(refusal(R"({"floor_center": [0, 0, 0], "half_width": -1})").find("/objects/1/room/half_width") !=
        std::string::npos);
  CHECK(refusal(R"({"floor_center": [0, 0, 0], "half_width": 1, "ceiling": true})").find("ceiling") !=
        std::string::npos);
  CHECK(refusal(R"({"floor_center": [0, 0, 0], "half_width": 1, "walls": "dome"})").find("/objects/1/room/walls") !=
        std::string::npos);
  CHECK(refusal(R"({"floor_center": [0, 0, 0], "half_width": 1, "walls": "box", "height": 2})") == "accepted");
  // A scene of surroundings alone has no subject to place cameras and lamps about.
  CHECK_THROWS_AS(build_scene(read_scene_text(
                      std::string(kHead) + R"("objects": [{"room": {"floor_center": [0, 0, 0], "half_width": 1}}]})",
                      "scene.json", ".")),
                  matbase::InputError);
}
