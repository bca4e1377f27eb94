// Prints what ambient occlusion to an error bound costs beside a fixed ray count: built-in objects
// in a library material under the paper's rig, each view rendered with ambient occlusion at 1 ray
// per camera sample, at the fixed count make_dataset used to size from the bound
// (ceil(0.25 / (error^2 spp))), and to the bound from each pixel's own trials, with the time,
// the rays per camera sample and the AO's RMSE against a reference of spp x 64 x 4 trials.
#include <cmath>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include "bench_scenes.h"
#include "image_error.h"
#include "matrender/render.h"

int main(int argc, char** argv) {
  CLI::App app{"ambient_occlusion_bench: ambient occlusion to an error bound beside a fixed ray count"};
  std::vector<std::string> objects{"chair", "vase"};
  std::string material = "metal:1";
  int resolution = 256, spp = 128, threads = 2;
  double error = 0.01;
  app.add_option("--objects", objects, "built-in objects")->capture_default_str();
  app.add_option("--material", material, "library material spec")->capture_default_str();
  app.add_option("--resolution", resolution, "image side in pixels")->capture_default_str();
  app.add_option("--spp", spp, "samples per pixel")->capture_default_str();
  app.add_option("--error", error, "the AO standard error bound")->capture_default_str();
  app.add_option("--threads", threads, "render threads")->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  const int fixed_rays = static_cast<int>(std::ceil(0.25 / (error * error * spp)));
  fmt::print("## Ambient occlusion, {} x {}, {} spp, bound {}, {} threads\n\n", resolution, resolution, spp, error, threads);
  fmt::print("| object | view | AO rays | seconds | rays per sample | AO RMSE against the reference | estimated RMS error |\n"
             "|---|---:|---|---:|---:|---:|---:|\n");
  for (const std::string& name : objects) {
    matrender::BuiltScene built = bench::builtin_in_library_material(name, material, 256);
    for (int view : {0, 1}) {
      const matrender::Camera camera = bench::framed_grid_view(built, view, resolution);
      matrender::RenderSettings settings;
      settings.threads = threads;
      settings.transparent_background = true;
      settings.aovs = matrender::AovAlpha | matrender::AovAmbientOcclusion;
      settings.samples_per_pixel = 4 * spp;
      settings.ambient_occlusion_rays = 64;
      settings.seed = 1000;
      matrender::FrameBuffers reference;
      matrender::render(built.scene, camera, settings, reference);
      settings.samples_per_pixel = spp;
      settings.seed = 1;
      struct Mode {
        std::string name;
        int rays;
        double error;
      };
      for (const Mode& mode : {Mode{"1 per sample", 1, 0.0}, Mode{fmt::format("{} per sample", fixed_rays), fixed_rays, 0.0},
                               Mode{fmt::format("to error {}", error), 1, error}}) {
        settings.ambient_occlusion_rays = mode.rays;
        settings.ambient_occlusion_error = mode.error;
        matrender::FrameBuffers frame;
        const matrender::RenderStats stats = matrender::render(built.scene, camera, settings, frame);
        fmt::print("| {} | {} | {} | {:.2f} | {:.1f} | {:.4f} | {:.4f} |\n", name, view, mode.name, stats.seconds,
                   static_cast<double>(stats.rays) / static_cast<double>(stats.camera_samples),
                   bench::covered_rmse(frame.ambient_occlusion, reference.ambient_occlusion, frame.alpha, reference.alpha),
                   stats.occlusion_rms_standard_error);
      }
    }
  }
  return 0;
}
