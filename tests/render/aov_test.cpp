// Each AOV equals the material and geometry at the first hit; labels and ids are never blended.
#include <catch2/catch.hpp>

#include <atomic>
#include <cmath>
#include <set>

#include "matrender/camera.h"
#include "matrender/render.h"
#include "matrender/scene.h"
#include "test_scenes.h"

using namespace matrender;

TEST_CASE("AOVs of a two-part plane equal the materials at the hit", "[render]") {
  // The plane's left half (x < 0) is part 0, the right half part 1.
  matgeom::TriangleMesh plane;
  plane.positions = {{-1, -1, 0}, {0, -1, 0}, {1, -1, 0}, {-1, 1, 0}, {0, 1, 0}, {1, 1, 0}};
  plane.triangles = {{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}};
  plane.triangle_parts = {0, 0, 1, 1};
  Material left, right;
  left.set(MaterialParameter::BaseColor, glm::vec3(0.2f, 0.4f, 0.6f));
  left.set(MaterialParameter::Roughness, 0.25f);
  left.set(MaterialParameter::Metallic, 0.0f);
  left.set(MaterialParameter::Specular, 0.3f).set(MaterialParameter::SpecularTint, 0.6f);
  left.set(MaterialParameter::Ior, 1.3f);
  left.label_id = 3;
  right.set(MaterialParameter::BaseColor, glm::vec3(0.9f, 0.1f, 0.5f));
  right.set(MaterialParameter::Roughness, 0.75f);
  right.set(MaterialParameter::Metallic, 1.0f);
  right.set(MaterialParameter::Specular, 0.7f).set(MaterialParameter::SpecularTint, 0.1f);
  right.set(MaterialParameter::Ior, 1.8f);
  right.label_id = 5;
  Scene scene;
  scene.add_mesh(plane, {scene.add_material(left), scene.add_material(right)});
  scene.add_lamp(PointLamp{glm::dvec3(0, 0, 1), 10.0, glm::dvec3(1.0)});

  // Straight down from 2 m; the 1.2 x 1.2 m footprint lies inside the 2 x 2 m plane.
  const Camera camera = Camera::look_at({0, 0, 2}, {0, 0, 0}, {0, 1, 0}, 2.0 * std::atan(0.3), 40, 40);
  RenderSettings settings;
  settings.samples_per_pixel = 8;
  settings.aovs = all_aovs();
  FrameBuffers frame;
  render(scene, camera, settings, frame);

  std::set<int> labels, parts;
  for (int y = 0; y < frame.height; ++y) {
    for (int x = 0; x < frame.width; ++x) {
      const size_t i = static_cast<size_t>(y) * frame.width + x;
      labels.insert(frame.label[i]);
      parts.insert(frame.part_id[i]);
      CHECK(frame.alpha[i] == 1.0f);
      CHECK(frame.normal_world[3 * i + 2] == Approx(1.0f));
      CHECK(frame.normal_camera[3 * i + 2] == Approx(1.0f));  // facing the camera (+Z toward viewer)
      CHECK(frame.depth[i] == Approx(2.0f).epsilon(1e-5));
      // Pixels away from the seam see one material only.
      if (x < frame.width / 2 - 2 || x >= frame.width / 2 + 2) {
        const bool is_left = x < frame.width / 2;
        const Material& m = is_left ? left : right;
        CHECK(frame.part_id[i] == (is_left ? 0 : 1));
        CHECK(frame.label[i] == m.label_id);
        // Every parameter of the table has its AOV.
        for (const matmaterial::MaterialParameterInfo& info : matmaterial::kMaterialParameters) {
          CAPTURE(info.name);
          const std::vector<float>& aov = frame.parameter(info.id);
          if (info.kind == matmaterial::ParameterKind::Color) {
            for (int c = 0; c < 3; ++c) CHECK(aov[3 * i + c] == Approx(m.color(info.id)[c]));
          } else {
            CHECK(aov[i] == Approx(m.scalar(info.id)));
          }
        }
      }
    }
  }
  CHECK(labels == std::set<int>{3, 5});  // never a blend of 3 and 5
  CHECK(parts == std::set<int>{0, 1});
}

TEST_CASE("Coverage, background and camera-space normals at an object's edge", "[render]") {
  Scene scene;
  scene.add_mesh(test_scenes::horizontal_square(1.0), {scene.add_material(test_scenes::lambert(0.5f))});
  scene.set_background(glm::vec3(0.25f));
  // Looking down at the square's far edge: the top of the image is background.
  const Camera camera = Camera::look_at({0.0, -1.0, 1.0}, {0.0, 0.5, 0.0}, {0, 0, 1}, 0.5, 32, 32);
  RenderSettings settings;
  settings.samples_per_pixel = 16;
  FrameBuffers frame;
  render(scene, camera, settings, frame);
  int background = 0, partial = 0;
  for (size_t i = 0; i < frame.alpha.size(); ++i) {
    if (frame.alpha[i] == 0.0f) {
      ++background;
      CHECK(frame.part_id[i] == -1);
      CHECK(frame.depth[i] == 0.0f);
      CHECK(frame.color[3 * i] == Approx(0.25f));
    } else if (frame.alpha[i] < 1.0f) {
      ++partial;
    }
    if (frame.alpha[i] > 0.0f) {
      // World +Z seen along d = (0, 1.5, -1) / |.|: camera +Z = -d, so the camera-space normal
      // is (0, sin e, cos e) with cos e = 1 / sqrt(3.25), the elevation's complement.
      const float cos_e = 1.0f / std::sqrt(3.25f);
      CHECK(frame.normal_camera[3 * i + 0] == Approx(0.0f).margin(1e-5));
      CHECK(frame.normal_camera[3 * i + 1] == Approx(std::sqrt(1.0f - cos_e * cos_e)).epsilon(1e-4));
      CHECK(frame.normal_camera[3 * i + 2] == Approx(cos_e).epsilon(1e-4));
    }
  }
  CHECK(background > 0);
  CHECK(partial > 0);  // the filter spreads the edge over more than one pixel row
}

TEST_CASE("Changing lamps re-renders without a BVH rebuild; progress and cancel work", "[render]") {
  Scene scene;
  scene.add_mesh(test_scenes::horizontal_square(2.0), {scene.add_material(test_scenes::lambert(0.5f))});
  scene.add_lamp(PointLamp{glm::dvec3(0, 0, 1), 10.0, glm::dvec3(1.0)});
  const Camera camera = Camera::look_at({0, -1, 1}, {0, 0, 0}, {0, 0, 1}, 0.8, 32, 32);
  RenderSettings settings;
  settings.samples_per_pixel = 2;
  double last_progress = 0.0;
  bool monotonic = true;
  settings.progress = [&](double f) {
    monotonic &= f >= last_progress;
    last_progress = f;
  };
  FrameBuffers first, second;
  render(scene, camera, settings, first);
  CHECK(last_progress == 1.0);
  CHECK(monotonic);
  const double build_seconds = scene.bvh_build_seconds();
  REQUIRE(scene.committed());

  scene.clear_lamps();
  scene.add_lamp(PointLamp{glm::dvec3(0, 0, 1), 40.0, glm::dvec3(1.0)});
  render(scene, camera, settings, second);
  CHECK(scene.bvh_build_seconds() == build_seconds);
  // Four times the power, four times the radiance (same seed, same paths).
  for (size_t i = 0; i < first.color.size(); ++i) CHECK(second.color[i] == Approx(4.0f * first.color[i]).epsilon(1e-5));
  CHECK_THROWS_AS(scene.add_mesh(test_scenes::horizontal_square(1.0), {0}), std::logic_error);

  std::atomic<bool> cancel{true};
  settings.cancel = &cancel;
  settings.progress = nullptr;
  FrameBuffers cancelled;
  CHECK(render(scene, camera, settings, cancelled).cancelled);
}

TEST_CASE("At millions of samples per pixel, progress comes within a pixel and a cancel stops it at once", "[render]") {
  Scene scene;
  scene.add_mesh(test_scenes::horizontal_square(1.0), {scene.add_material(test_scenes::lambert(0.5f))});
  scene.add_lamp(PointLamp{glm::dvec3(0, 0, 1), 10.0, glm::dvec3(1.0)});
  const Camera camera = Camera::look_at({0, 0, 2}, {0, 0, 0}, {0, 1, 0}, 0.5, 4, 4);
  RenderSettings settings;
  settings.samples_per_pixel = 1 << 24;  // 268 M samples in all: minutes of work
  settings.threads = 2;
  std::atomic<bool> cancel{false};
  double first_progress = 0.0;
  settings.cancel = &cancel;
  // The first report cancels: it must come long before any pixel, let alone a tile, is done.
  settings.progress = [&](double fraction) {
    if (first_progress == 0.0) first_progress = fraction;
    cancel = true;
  };
  FrameBuffers frame;
  const RenderStats stats = render(scene, camera, settings, frame);
  CHECK(stats.cancelled);
  CHECK(first_progress > 0.0);
  CHECK(first_progress < 1e-3);
  // Each thread stops at its next packet of 16 samples after the flag is set: at most a progress
  // interval (65,536 samples) per thread, plus a packet, are taken.
  CHECK(stats.camera_samples <= 2u * (65536u + 16u) + 65536u);
}
