// Blender 3.4 Cycles beside libmatrender on the same scene, in one run: the bumpy sphere of
// render_bench in the bench material under the paper's rig, rendered by both at the same
// sample counts and threads. Prints each renderer's time and error against its own converged
// reference, the time each needs to reach the same error (and their ratio), and how far the two
// converged images are apart (accuracy). Needs Debian's `blender` (3.4) on PATH or --blender;
// Blender is a reference here, never a dependency of the product.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include "bench_scenes.h"
#include "image_error.h"
#include "matrender/paper_setup.h"
#include "matrender/render.h"
#include "matrender/rig_lights.h"
#include "shaders_ref/cycles_reference.h"

namespace {

struct Curve {
  std::vector<double> seconds, error;  // by increasing sample count
};

// Seconds to reach `target` error, interpolated log-log between the measured points; NaN when
// the curve never gets there.
double seconds_to_reach(const Curve& curve, double target) {
  for (size_t k = 0; k < curve.error.size(); ++k) {
    if (curve.error[k] > target) continue;
    if (k == 0) return curve.seconds[0];
    const double t = (std::log(curve.error[k - 1]) - std::log(target)) /
                     (std::log(curve.error[k - 1]) - std::log(curve.error[k]));
    return std::exp(std::log(curve.seconds[k - 1]) + t * (std::log(curve.seconds[k]) - std::log(curve.seconds[k - 1])));
  }
  return std::nan("");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"cycles_side_by_side: libmatrender beside Blender 3.4 Cycles, time to the same error"};
  size_t triangles = 10'000;
  int resolution = 256, threads = 2, reference_spp = 1024;
  std::vector<int> spp_list = {1, 4, 16, 64, 256};
  std::string blender = "blender", work = "cycles_side_by_side_out";
  app.add_option("--triangles", triangles, "triangles of the bumpy sphere")->capture_default_str();
  app.add_option("--resolution", resolution, "image side in pixels")->capture_default_str();
  app.add_option("--threads", threads, "threads for both renderers")->capture_default_str();
  app.add_option("--spp", spp_list, "sample counts to time")->capture_default_str();
  app.add_option("--reference-spp", reference_spp, "samples of each renderer's converged reference")
      ->capture_default_str();
  app.add_option("--blender", blender, "Blender 3.4 executable")->capture_default_str();
  app.add_option("--work", work, "folder for the scene description and Cycles' EXRs")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  std::sort(spp_list.begin(), spp_list.end());

  shaders_ref::CyclesScene cycles_scene;
  cycles_scene.mesh = bench::displaced_sphere(triangles);
  cycles_scene.material = bench::bench_material();
  cycles_scene.lamps = matrender::rig_lights(matrender::paper_rig(cycles_scene.mesh));
  cycles_scene.camera = matrender::paper_view(cycles_scene.mesh, resolution, resolution);
  const matgeom::TriangleMesh& mesh = cycles_scene.mesh;
  const matrender::Camera& camera = cycles_scene.camera;

  // Cycles first, alone on the machine; its reference is rendered last.
  std::vector<shaders_ref::CyclesRender> cycles_renders;
  for (const int spp : spp_list) cycles_renders.push_back({spp, 0, "", 0.0});
  cycles_renders.push_back({reference_spp, 0, "", 0.0});
  fmt::print(stderr, "rendering with Blender into {} ...\n", work);
  try {
    shaders_ref::render_with_cycles(cycles_scene, cycles_renders, threads, work, blender);
  } catch (const std::exception& error) {
    fmt::print(stderr, "cycles_side_by_side: {}\n", error.what());
    return 1;
  }

  matrender::Scene scene;
  scene.add_mesh(mesh, {scene.add_material(cycles_scene.material)});
  for (const matrender::Light& lamp : cycles_scene.lamps) scene.add_light(lamp);
  scene.commit();
  const auto render_ours = [&](int spp, double* seconds) {
    matrender::RenderSettings settings;
    settings.samples_per_pixel = spp;
    settings.threads = threads;
    settings.aovs = 0;
    matrender::FrameBuffers frame;
    *seconds = matrender::render(scene, camera, settings, frame).seconds;
    return frame.color;
  };
  double ours_reference_seconds;
  const std::vector<float> ours_reference = render_ours(reference_spp, &ours_reference_seconds);
  const std::vector<float> cycles_reference =
      shaders_ref::read_rgb_exr(cycles_renders.back().exr_path, resolution, resolution);

  Curve ours, cycles;
  fmt::print("## libmatrender beside Blender 3.4 Cycles: bumpy sphere, {} triangles, paper rig, {}x{}, {} threads\n\n",
             mesh.triangle_count(), resolution, resolution, threads);
  fmt::print("BVH build (ours): {:.1f} ms. Cycles' times are whole render calls (scene sync, BVH, sampling, EXR).\n\n",
             1e3 * scene.bvh_build_seconds());
  fmt::print("| spp | ours s | ours RMSE | Cycles s | Cycles RMSE |\n|---:|---:|---:|---:|---:|\n");
  for (size_t k = 0; k < spp_list.size(); ++k) {
    const int spp = spp_list[k];
    double seconds;
    const std::vector<float> image = render_ours(spp, &seconds);
    ours.seconds.push_back(seconds + scene.bvh_build_seconds());
    ours.error.push_back(bench::rmse(image, ours_reference));
    cycles.seconds.push_back(cycles_renders[k].seconds);
    cycles.error.push_back(
        bench::rmse(shaders_ref::read_rgb_exr(cycles_renders[k].exr_path, resolution, resolution), cycles_reference));
    fmt::print("| {} | {:.3f} | {:.5f} | {:.3f} | {:.5f} |\n", spp, ours.seconds.back(), ours.error.back(),
               cycles.seconds.back(), cycles.error.back());
  }
  fmt::print("\nReferences: ours {} spp in {:.2f} s, Cycles {} spp in {:.2f} s.\n\n", reference_spp,
             ours_reference_seconds, reference_spp, cycles_renders.back().seconds);

  fmt::print("| RMSE reached | ours s | Cycles s | Cycles / ours |\n|---:|---:|---:|---:|\n");
  for (size_t k = 0; k < cycles.error.size(); ++k) {
    const double target = cycles.error[k];
    const double a = seconds_to_reach(ours, target), b = seconds_to_reach(cycles, target);
    fmt::print("| {:.5f} | {:.3f} | {:.3f} | {:.2f} |\n", target, a, b, b / a);
  }
  const double mean_ours = bench::mean(ours_reference), mean_cycles = bench::mean(cycles_reference);
  fmt::print("\nConverged images: RMSE between them {:.5f} (mean pixel {:.5f} ours, {:.5f} Cycles, ratio {:.4f}).\n",
             bench::rmse(ours_reference, cycles_reference), mean_ours, mean_cycles, mean_ours / mean_cycles);
  return 0;
}
