// Light selection: the noise of importance selection (each shading point picks a light in
// proportion to a bound on the irradiance it can give there) against Cycles 3.4's uniform choice,
// at equal samples and in one run, on two scenes: the built-in vase under the paper's light rig,
// and a room lit by 14 lamps of which 10 light only its back wall. Both converge to the same
// image; each row gives the RMSE against a converged reference, the seconds, and the ratios.
// Timings are only meaningful on an otherwise idle machine.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include "bench_scenes.h"
#include "image_error.h"
#include "matgeom/camera_grid.h"
#include "matrender/paper_setup.h"
#include "matrender/render.h"
#include "matrender/scene_builder.h"

namespace {

struct BenchScene {
  std::string name;
  matrender::Scene scene;
  matrender::Camera camera;
};

// A quad from `corner` along edges a and b, wound so that its front faces a x b.
matgeom::TriangleMesh quad(const glm::vec3& corner, const glm::vec3& a, const glm::vec3& b) {
  matgeom::TriangleMesh m;
  m.positions = {corner, corner + a, corner + a + b, corner + b};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

matrender::RectLamp lamp_at(const glm::dvec3& position, const glm::dvec3& target, double size, double power) {
  matrender::RectLamp lamp;
  lamp.light_to_world = matgeom::look_at_camera_to_world(position, target, {0, 0, 1});
  lamp.size_x = lamp.size_y = size;
  lamp.power = power;
  return lamp;
}

BenchScene paper_rig_scene(int resolution) {
  matrender::ObjectDescription vase;
  vase.source = matrender::BuiltinObject{"vase", 0};
  matrender::SceneDescription description = matrender::paper_object_scene(vase);
  description.camera.width = description.camera.height = resolution;
  matrender::BuiltScene built = matrender::build_scene(description);
  return {"vase under the paper's rig (" + std::to_string(built.scene.lamps().size()) + " lamps)",
          std::move(built.scene), built.camera};
}

// A room 4 m wide: a floor, a back wall 2 m behind a bumpy sphere (render_bench's, in its
// material), 10 lamps 0.3 m in front of the wall facing it (they light the wall only) and 4 lamps
// around the sphere facing it.
BenchScene back_lit_room(int resolution) {
  BenchScene s{"room with 14 lamps, 10 lighting only its back wall", {}, {}};
  matrender::Material white;
  white.set(matrender::MaterialParameter::BaseColor, glm::vec3(0.8f));
  white.set(matrender::MaterialParameter::Roughness, 0.6f);
  const uint32_t wall_material = s.scene.add_material(white);
  s.scene.add_mesh(quad({-2.0f, -3.0f, 0.0f}, {4.0f, 0.0f, 0.0f}, {0.0f, 5.0f, 0.0f}), {wall_material});  // floor
  s.scene.add_mesh(quad({-2.0f, 2.0f, 0.0f}, {0.0f, 0.0f, 2.5f}, {4.0f, 0.0f, 0.0f}), {wall_material});   // back wall
  matgeom::TriangleMesh sphere = bench::displaced_sphere(20000);
  for (glm::vec3& p : sphere.positions) p += glm::vec3(0.0f, 0.0f, 0.35f);
  s.scene.add_mesh(sphere, {s.scene.add_material(bench::bench_material())});
  for (int k = 0; k < 10; ++k) {
    const double x = -1.8 + 0.4 * k;
    s.scene.add_lamp(lamp_at({x, 1.7, 0.4 + 0.15 * (k % 4)}, {x, 2.0, 0.6 + 0.15 * (k % 4)}, 0.25, 40.0));
  }
  for (const glm::dvec3& at : {glm::dvec3(1.0, -1.0, 0.8), glm::dvec3(-1.0, -1.0, 0.8), glm::dvec3(0.8, 0.6, 1.2),
                               glm::dvec3(-0.8, 0.6, 1.2)})
    s.scene.add_lamp(lamp_at(at, {0.0, 0.0, 0.2}, 0.4, 60.0));
  s.camera = matrender::Camera::look_at({0.0, -2.2, 0.9}, {0.0, 0.5, 0.5}, {0, 0, 1}, 0.9, resolution, resolution);
  return s;
}

std::vector<float> render_colour(BenchScene& s, matrender::LightSelection selection, int spp, uint32_t seed,
                                 int threads, double* seconds) {
  matrender::RenderSettings settings;
  settings.samples_per_pixel = spp;
  settings.seed = seed;
  settings.threads = threads;
  settings.aovs = 0;
  settings.light_selection = selection;
  matrender::FrameBuffers frame;
  const matrender::RenderStats stats = matrender::render(s.scene, s.camera, settings, frame);
  if (seconds) *seconds = stats.seconds;
  return frame.color;
}

void compare(BenchScene& s, int reference_spp, const std::vector<int>& spp_list, int threads) {
  const std::vector<float> reference =
      render_colour(s, matrender::LightSelection::Importance, reference_spp, 1000, threads, nullptr);
  fmt::print("\n## {}, {}x{}, {} threads, against a {} spp reference\n\n", s.name, s.camera.width, s.camera.height,
             threads, reference_spp);
  fmt::print("| spp | uniform RMSE | uniform s | importance RMSE | importance s | MSE ratio | time-to-error ratio |\n"
             "|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const int spp : spp_list) {
    double uniform_seconds = 0.0, importance_seconds = 0.0;
    const double uniform = bench::rmse(
        render_colour(s, matrender::LightSelection::Uniform, spp, 1, threads, &uniform_seconds), reference);
    const double importance = bench::rmse(
        render_colour(s, matrender::LightSelection::Importance, spp, 1, threads, &importance_seconds), reference);
    const double mse_ratio = uniform * uniform / (importance * importance);
    // Error falls as 1 / samples: the time uniform needs for importance's error, over importance's.
    fmt::print("| {} | {:.5f} | {:.3f} | {:.5f} | {:.3f} | {:.2f} | {:.2f} |\n", spp, uniform, uniform_seconds,
               importance, importance_seconds, mse_ratio, mse_ratio * uniform_seconds / importance_seconds);
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Noise of importance light selection against uniform selection, at equal samples, in one run."};
  int resolution = 128, reference_spp = 4096, threads = 2;
  std::vector<int> spp_list = {16, 64, 256};
  app.add_option("--resolution", resolution, "image side in pixels")->capture_default_str()->check(CLI::Range(8, 2048));
  app.add_option("--reference-spp", reference_spp, "samples per pixel of the converged reference")
      ->capture_default_str()
      ->check(CLI::Range(64, 1 << 20));
  app.add_option("--spp", spp_list, "sample counts compared")->check(CLI::Range(1, 1 << 16));
  app.add_option("--threads", threads, "render threads")->capture_default_str()->check(CLI::Range(1, 256));
  CLI11_PARSE(app, argc, argv);
  try {
    BenchScene rig = paper_rig_scene(resolution);
    compare(rig, reference_spp, spp_list, threads);
    BenchScene room = back_lit_room(resolution);
    compare(room, reference_spp, spp_list, threads);
  } catch (const std::exception& e) {
    fmt::print(stderr, "light_selection_bench: {}\n", e.what());
    return 1;
  }
  return 0;
}
