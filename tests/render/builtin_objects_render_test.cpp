// Every built-in object renders: finite pixels, nothing discarded, the object in view, and its
// material labels in the label AOV.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <set>

#include "test_scenes.h"
#include "matgeom/bounding_sphere.h"
#include "matgeom/builtin/builtin_objects.h"
#include "matgeom/camera_grid.h"
#include "matrender/asset.h"
#include "matrender/render.h"
#include "matrender/paper_setup.h"
#include "matrender/scene.h"
#include "matrender/scene_builder.h"
#include "scene/scene_data.h"

TEST_CASE("Every built-in object renders with finite pixels", "[render]") {
  const std::string name = GENERATE(from_range(matgeom::builtin_object_names()));
  INFO(name);
  const matgeom::ObjectAsset asset = matgeom::make_builtin_object(name, 1);
  matrender::Scene scene;
  matrender::add_asset(scene, asset);
  const matgeom::Sphere bounds = matgeom::minimal_enclosing_sphere(asset.mesh.positions);
  scene.set_background(glm::vec3(0.4f));
  scene.add_lamp(matrender::PointLamp{bounds.center + glm::dvec3(0.5, -1.0, 2.0) * bounds.radius, 40.0 * bounds.radius * bounds.radius,
                                        glm::dvec3(1.0)});
  matrender::Camera camera;
  const glm::dvec3 eye = bounds.center + 2.6 * bounds.radius * glm::normalize(glm::dvec3(1.0, -1.3, 0.9));
  camera.camera_to_world = matgeom::look_at_camera_to_world(eye, bounds.center, glm::dvec3(0.0, 0.0, 1.0));
  camera.vertical_fov = 0.8;
  camera.width = camera.height = 40;
  matrender::RenderSettings settings;
  settings.samples_per_pixel = 4;
  settings.aovs = matrender::all_aovs();
  matrender::FrameBuffers frame;
  const matrender::RenderStats stats = matrender::render(scene, camera, settings, frame);
  CHECK(stats.discarded_samples == 0);
  CHECK(test_scenes::all_finite(frame.color));
  CHECK(test_scenes::all_finite(frame.normal_world));
  CHECK(test_scenes::all_finite(frame.depth));
  double coverage = 0.0;
  for (float a : frame.alpha) coverage += a;
  coverage /= static_cast<double>(frame.alpha.size());
  CHECK(coverage > 0.1);
  // Every label the object's materials carry shows up, and no other.
  std::set<int32_t> expected = {0}, seen;
  for (const matmaterial::MaterialInputs& m : asset.materials) expected.insert(m.label_id);
  for (int32_t label : frame.label) seen.insert(label);
  CHECK(std::includes(expected.begin(), expected.end(), seen.begin(), seen.end()));
}

TEST_CASE("An object's uv_scale scales the UV pass's texel density", "[render]") {
  // The pass gives each part s times the paper's texels per metre, so its UV area scales by s^2
  // (the pillow's charts fit a tile at every s here, so none is shrunk to fit).
  auto uv_area = [](double scale) {
    matrender::ObjectDescription pillow;
    pillow.source = matrender::BuiltinObject{"pillow", 0};
    pillow.uv_pass = matrender::UvPassMode::Always;
    pillow.uv_scale = scale;
    const matrender::BuiltScene built = matrender::build_scene(matrender::paper_object_scene(pillow));
    const matrender::MeshData& mesh = built.scene.data().meshes[built.object_meshes.front()];
    double area = 0.0;
    for (const glm::uvec3& t : mesh.triangles) {
      const glm::vec2 a = mesh.uvs[t.x], b = mesh.uvs[t.y], c = mesh.uvs[t.z];
      area += 0.5 * std::abs(static_cast<double>((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)));
    }
    return area;
  };
  const double unit = uv_area(1.0);
  CHECK(uv_area(0.5) == Approx(0.25 * unit).epsilon(0.02));
  CHECK(uv_area(0.2) == Approx(0.04 * unit).epsilon(0.02));
}
