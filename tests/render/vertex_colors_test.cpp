// A scan's vertex colours as its base colour: interpolated across each triangle, equal to a
// constant material of the same colour where they are constant, and ignored by a material put on
// the part in their place. Parts of a file chosen by only_parts and except_parts.
#include <catch2/catch.hpp>

#include <cmath>
#include <numeric>
#include <string>

#include "matgeom/io/ply/ply_io.h"
#include "matrender/render.h"
#include "matrender/scene_builder.h"
#include "matrender/scene_file.h"
#include "support/temp_dir.h"

using namespace matrender;
using Catch::Matchers::Contains;

namespace {

// Two squares side by side on z = 0, each a part ("object_1" at x < 0, "object_2" at x > 0),
// with the colours `left` at x = -1 and `right` at x = +1 (0 at the shared edge, a blend).
matgeom::TriangleMesh two_squares(const glm::vec3& left, const glm::vec3& right) {
  matgeom::TriangleMesh mesh;
  mesh.positions = {{-1, -1, 0}, {0, -1, 0}, {0, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {1, 1, 0}};
  const glm::vec3 middle = 0.5f * (left + right);
  mesh.colors = {left, middle, middle, left, right, right};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}, {1, 4, 5}, {1, 5, 2}};
  mesh.triangle_parts = {0, 0, 1, 1};
  mesh.part_names = {"object_1", "object_2"};
  return mesh;
}

// The squares seen from straight above, filling a 33 x 33 frame (the middle column at x = 0),
// under a uniform white world; `material` (a name) on every part, with `color`, if given.
std::string scene_json(const std::string& mesh, const std::string& material = "", const glm::vec3& color = {}) {
  std::string materials, assigned;
  if (!material.empty()) {
    materials = R"("materials": {")" + material + R"(": {"base_color": [)" + std::to_string(color.x) + ", " +
                std::to_string(color.y) + ", " + std::to_string(color.z) + "]}}, ";
    assigned = R"(, "material": ")" + material + R"(")";
  }
  return R"({"camera": {"position": [0, 0, 4], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov_deg": 20,
             "width": 33, "height": 33}, )" + materials + R"("lights": [], "background": [1, 1, 1],
             "objects": [{"mesh": ")" + mesh + R"(")" + assigned + "}]}";
}

FrameBuffers rendered(const std::string& json, const std::string& folder) {
  BuiltScene built = build_scene(read_scene_text(json, "vertex colour test", folder));
  RenderSettings settings;
  settings.samples_per_pixel = 16;
  settings.seed = 3;
  settings.aovs = parameter_aov(MaterialParameter::BaseColor) | AovAlpha;
  FrameBuffers frame;
  render(built.scene, built.camera, settings, frame);
  return frame;
}

}  // namespace

TEST_CASE("Vertex colours are the base colour, interpolated across each triangle", "[render]") {
  TempDir dir;
  const glm::vec3 left(0.8f, 0.1f, 0.05f), right(0.05f, 0.3f, 0.9f);
  matgeom::write_ply(two_squares(left, right), dir.file("squares.ply"));
  const FrameBuffers frame = rendered(scene_json("squares.ply"), dir.path().string());
  const std::vector<float>& base = frame.parameter(MaterialParameter::BaseColor);
  REQUIRE(base.size() == 3u * 33 * 33);
  // The middle pixel looks at x = 0, where the colour is the blend; toward the edges it nears the
  // end colours, monotonically in every channel.
  const auto at = [&](int x, int y, int c) { return base[3 * (static_cast<size_t>(y) * 33 + x) + c]; };
  // PLY stores colours as sRGB bytes: the ends are the bytes' colours, a hair off the originals.
  for (int c = 0; c < 3; ++c) CHECK(at(16, 16, c) == Approx(0.5f * (left[c] + right[c])).margin(0.004));
  for (int x = 1; x < 33; ++x)
    for (int c = 0; c < 3; ++c) {
      if (left[c] > right[c]) CHECK(at(x, 16, c) <= at(x - 1, 16, c));
      else CHECK(at(x, 16, c) >= at(x - 1, 16, c));
    }
}

TEST_CASE("A constant vertex colour renders as a constant material of that colour; a material put in its place ignores it",
          "[render]") {
  TempDir dir;
  // Bytes exactly: 128/255 sRGB per channel is what the file holds either way.
  const float grey = static_cast<float>(std::pow((128.0 / 255.0 + 0.055) / 1.055, 2.4));
  const glm::vec3 color(grey, 0.5f * grey, 0.25f * grey);
  matgeom::TriangleMesh mesh = two_squares(color, color);
  matgeom::write_ply(mesh, dir.file("coloured.ply"));
  const matgeom::TriangleMesh read = matgeom::read_ply(dir.file("coloured.ply"));
  const glm::vec3 stored = read.colors.front();
  mesh.colors.clear();
  matgeom::write_ply(mesh, dir.file("plain.ply"));

  const FrameBuffers coloured = rendered(scene_json("coloured.ply"), dir.path().string());
  const FrameBuffers plain = rendered(scene_json("plain.ply", "paint", stored), dir.path().string());
  REQUIRE(coloured.color.size() == plain.color.size());
  // The same samples meet the same inputs: the images agree to rounding.
  for (size_t i = 0; i < coloured.color.size(); ++i) CHECK(coloured.color[i] == Approx(plain.color[i]).margin(1e-5));

  // A material given to the parts replaces the colours.
  const FrameBuffers replaced = rendered(scene_json("coloured.ply", "paint", stored), dir.path().string());
  for (size_t i = 0; i < coloured.color.size(); ++i) CHECK(replaced.color[i] == Approx(plain.color[i]).margin(1e-5));
  const FrameBuffers white = rendered(scene_json("coloured.ply", "white", glm::vec3(1.0f)), dir.path().string());
  const std::vector<float>& base = white.parameter(MaterialParameter::BaseColor);
  for (const float channel : base) CHECK(channel == 1.0f);
}

TEST_CASE("A scene object is the parts of a file only_parts names, or every part but those except_parts names",
          "[render]") {
  TempDir dir;
  matgeom::write_ply(two_squares(glm::vec3(0.5f), glm::vec3(0.5f)), dir.file("squares.ply"));
  const auto built = [&](const std::string& keys) {
    return build_scene(read_scene_text(R"({"camera": {"position": [0, 0, 4], "look_at": [0, 0, 0], "up": [0, 1, 0]},
        "lights": [], "objects": [{"mesh": "squares.ply", )" + keys + "}]}", "parts test", dir.path().string()));
  };
  const BuiltScene left = built(R"("only_parts": ["object_1"])");
  CHECK(left.object_surfaces.front().part_names == std::vector<std::string>{"object_1"});
  CHECK(left.bounds.center.x < 0.0);
  const BuiltScene right = built(R"("except_parts": ["object_1"])");
  CHECK(right.object_surfaces.front().part_names == std::vector<std::string>{"object_2"});
  CHECK(right.bounds.center.x > 0.0);
  CHECK(built(R"("only_parts": ["object_1", "object_2"])").object_surfaces.front().triangle_count() == 4);

  const auto error = [&](const std::string& keys) {
    try {
      built(keys);
    } catch (const matbase::InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK_THAT(error(R"("only_parts": ["object_9"])"),
             Contains("/objects/0") && Contains("object_9") && Contains("\"object_1\", \"object_2\""));
  CHECK_THAT(error(R"("except_parts": ["object_1", "object_2"])"), Contains("leaves no part"));
  CHECK_THAT(error(R"("only_parts": ["object_1"], "except_parts": ["object_2"])"), Contains("not both"));
  CHECK_THAT(error(R"("only_parts": [])"), Contains("one or more part names"));
  CHECK_THAT(error(R"("only_parts": "object_1")"), Contains("a list of part names"));
}
