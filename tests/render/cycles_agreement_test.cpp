// libmatrender against Blender 3.4 Cycles itself (optional: MATPREDICT_BLENDER_TESTS, ctest label
// "blender"; needs Debian's `blender`). A bumpy sphere under the paper's rig, seen from the
// paper's grid cell (5, 16), in several Principled materials, rendered by both renderers with two
// seeds each. Each renderer's noise variance is estimated from its own two images; if the two
// renderers compute the same integral, the mean squared difference of their seed-averaged
// images is the sum of the two noise variances of the averages, and nothing more.
#include <cmath>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "matgeom/bounding_sphere.h"
#include "matgeom/camera_grid.h"
#include "matgeom/light_rig.h"
#include "matgeom/tangents.h"
#include "matrender/render.h"
#include "shaders_ref/cycles_reference.h"

namespace {

constexpr int kResolution = 64;
constexpr int kSamples = 256;

// A sphere of radius 0.3 m with bumps, its vertex normals smooth: curvature, self-shadowing and
// every angle of incidence in one object.
matgeom::TriangleMesh bumpy_sphere() {
  constexpr int kRings = 48, kSegments = 96;
  matgeom::TriangleMesh mesh;
  for (int i = 0; i <= kRings; ++i)
    for (int j = 0; j <= kSegments; ++j) {
      const double theta = M_PI * i / kRings, phi = 2.0 * M_PI * j / kSegments;
      const double r = 0.3 * (1.0 + 0.08 * std::sin(7.0 * theta) * std::sin(5.0 * phi));
      mesh.positions.emplace_back(r * std::sin(theta) * std::cos(phi), r * std::sin(theta) * std::sin(phi),
                                  0.35 + r * std::cos(theta));
    }
  for (int i = 0; i < kRings; ++i)
    for (int j = 0; j < kSegments; ++j) {
      const uint32_t a = i * (kSegments + 1) + j, b = a + kSegments + 1;
      if (i > 0) mesh.triangles.push_back({a, b, a + 1});
      if (i + 1 < kRings) mesh.triangles.push_back({a + 1, b, b + 1});
    }
  matgeom::compute_vertex_normals(mesh);
  return mesh;
}

shaders_ref::CyclesScene paper_scene(const matrender::Material& material) {
  shaders_ref::CyclesScene scene;
  scene.mesh = bumpy_sphere();
  scene.material = material;
  const matgeom::Sphere bound = matgeom::minimal_enclosing_sphere(scene.mesh.positions);
  matgeom::LightRigOptions options;
  options.target_illuminance_lux = 1000.0;
  for (const matgeom::RigLight& light : matgeom::make_light_rig(bound.center, bound.radius, options).lights) {
    REQUIRE(light.kind == matgeom::RigLightKind::Area);  // spots only come for objects under 0.15 m
    matrender::RectLight rect;
    rect.light_to_world = light.light_to_world;
    rect.size_x = light.size_x;
    rect.size_y = light.size_y;
    rect.power = light.power;
    rect.color = light.color;
    scene.lamps.push_back(rect);
  }
  matgeom::CameraGridSpec grid;
  grid.center = bound.center;
  scene.camera.camera_to_world = matgeom::grid_camera(grid, 5, 16).camera_to_world;
  scene.camera.width = scene.camera.height = kResolution;
  return scene;
}

std::vector<float> render_ours(const shaders_ref::CyclesScene& cycles_scene, uint32_t seed) {
  matrender::Scene scene;
  scene.add_mesh(cycles_scene.mesh, {scene.add_material(cycles_scene.material)});
  for (const matrender::RectLight& lamp : cycles_scene.lamps) scene.add_light(lamp);
  matrender::RenderSettings settings;
  settings.samples_per_pixel = kSamples;
  settings.seed = seed;
  settings.aovs = 0;
  matrender::FrameBuffers frame;
  matrender::render(scene, cycles_scene.camera, settings, frame);
  return frame.color;
}

struct Agreement {
  double noise_ours = 0.0, noise_cycles = 0.0;  // variance of one image's pixel values about the truth
  double difference = 0.0;                       // mean squared difference of the seed averages
  double mean_ours = 0.0, mean_cycles = 0.0;
};

Agreement compare(const std::vector<float>& ours0, const std::vector<float>& ours1, const std::vector<float>& cycles0,
                  const std::vector<float>& cycles1) {
  Agreement a;
  const double n = static_cast<double>(ours0.size());
  for (size_t i = 0; i < ours0.size(); ++i) {
    a.noise_ours += 0.5 * (double(ours0[i]) - ours1[i]) * (double(ours0[i]) - ours1[i]) / n;
    a.noise_cycles += 0.5 * (double(cycles0[i]) - cycles1[i]) * (double(cycles0[i]) - cycles1[i]) / n;
    const double d = 0.5 * (double(ours0[i]) + ours1[i]) - 0.5 * (double(cycles0[i]) + cycles1[i]);
    a.difference += d * d / n;
    a.mean_ours += 0.5 * (double(ours0[i]) + ours1[i]) / n;
    a.mean_cycles += 0.5 * (double(cycles0[i]) + cycles1[i]) / n;
  }
  return a;
}

struct Case {
  std::string name;
  glm::vec3 base_color;
  float metallic, roughness, specular, specular_tint;
};

}  // namespace

TEST_CASE("Renders agree with Blender 3.4 Cycles up to noise", "[render][blender]") {
  REQUIRE(shaders_ref::cycles_available());
  const std::vector<Case> cases = {
      {"dielectric_rough_0.35", {0.7f, 0.5f, 0.3f}, 0.0f, 0.35f, 0.5f, 0.0f},
      {"dielectric_glossy_0.05", {0.2f, 0.4f, 0.8f}, 0.0f, 0.05f, 0.5f, 0.0f},
      {"dielectric_rough_1_specular_1_tint_1", {0.9f, 0.9f, 0.2f}, 0.0f, 1.0f, 1.0f, 1.0f},
      {"metal_0.2", {0.95f, 0.65f, 0.3f}, 1.0f, 0.2f, 0.5f, 0.0f},
      {"metal_0", {0.9f, 0.9f, 0.9f}, 1.0f, 0.0f, 0.5f, 0.0f},
      {"half_metal_0.6", {0.5f, 0.8f, 0.5f}, 0.5f, 0.6f, 0.5f, 0.0f},
  };
  const std::string work = "cycles_agreement_out";
  for (const Case& c : cases) {
    matrender::Material material;
    material.base_color.value = c.base_color;
    material.metallic.value = c.metallic;
    material.roughness.value = c.roughness;
    material.specular = c.specular;
    material.specular_tint = c.specular_tint;
    const shaders_ref::CyclesScene scene = paper_scene(material);
    std::vector<shaders_ref::CyclesRender> renders = {{kSamples, 1, "", 0.0}, {kSamples, 2, "", 0.0}};
    shaders_ref::render_with_cycles(scene, renders, 2, work + "/" + c.name);
    const Agreement a =
        compare(render_ours(scene, 1), render_ours(scene, 2),
                shaders_ref::read_rgb_exr(renders[0].exr_path, kResolution, kResolution),
                shaders_ref::read_rgb_exr(renders[1].exr_path, kResolution, kResolution));
    const double expected = 0.5 * (a.noise_ours + a.noise_cycles);
    INFO(c.name << ": mean squared difference " << a.difference << ", noise alone " << expected
                << "; mean pixel ours " << a.mean_ours << ", Cycles " << a.mean_cycles);
    // The three mean squares each estimate their expectation from 12288 pixel values; with
    // neighbouring pixels correlated by the 1.5 px filter and heavy-tailed path-tracing noise,
    // count on at least 500 independent ones: relative standard deviation sqrt(2 / 500) = 6 %,
    // four of them 25 %.
    CHECK(a.difference <= 1.25 * expected);
    // Energy: the image means agree to 1 %, far above their noise (about 0.1 % here).
    CHECK(a.mean_ours == Approx(a.mean_cycles).epsilon(0.01));
  }
}
