// Prints the denoiser's figures: on built-in objects in library materials under the paper's rig,
// the image's RMSE against a converged reference (percent of the object's mean) at several
// sample counts, raw and denoised, with the time each took (render, then the filter), in one run.
#include <cmath>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include "bench_scenes.h"
#include "image_error.h"
#include "matrender/render.h"


int main(int argc, char** argv) {
  CLI::App app{"denoise_bench: the denoiser's error against a converged reference, raw beside denoised"};
  int resolution = 192, reference_spp = 2048, threads = 2;
  std::vector<int> spps{4, 16, 64, 128};
  std::vector<std::string> cases{"vase:wood:1", "chair:fabric:1", "vase:metal:1"};
  app.add_option("--resolution", resolution, "image side in pixels")->capture_default_str();
  app.add_option("--reference-spp", reference_spp, "samples per pixel of the reference")->capture_default_str();
  app.add_option("--spp", spps, "sample counts compared")->capture_default_str();
  app.add_option("--cases", cases, "OBJECT:MATERIAL (a library spec)")->capture_default_str();
  app.add_option("--threads", threads, "render threads")->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  fmt::print("## Denoising: RMSE against a {} spp reference, % of the object's mean, {}x{}, {} threads\n\n",
             reference_spp, resolution, resolution, threads);
  fmt::print("| object | material | spp | raw RMSE | raw s | denoised RMSE | denoised s |\n|---|---|---:|---:|---:|---:|---:|\n");
  for (const std::string& spec : cases) {
    const size_t colon = spec.find(':');
    const std::string object = spec.substr(0, colon), material = spec.substr(colon + 1);
    matrender::BuiltScene built = bench::builtin_in_library_material(object, material, 512);
    const matrender::Camera camera = bench::framed_grid_view(built, 1, resolution);
    matrender::RenderSettings settings;
    settings.threads = threads;
    settings.transparent_background = true;
    settings.aovs = matrender::AovAlpha;
    settings.samples_per_pixel = reference_spp;
    settings.seed = 1000;
    matrender::FrameBuffers reference;
    matrender::render(built.scene, camera, settings, reference);
    const double brightness = bench::mean(reference.color) / std::max(bench::mean(reference.alpha), 1e-9);
    for (const int spp : spps) {
      settings.samples_per_pixel = spp;
      settings.seed = 1;
      std::string row = fmt::format("| {} | {} | {} ", object, material, spp);
      for (const bool denoised : {false, true}) {
        settings.denoise = denoised ? matrender::Denoising::Filter : matrender::Denoising::Off;
        matrender::FrameBuffers frame;
        const matrender::RenderStats stats = matrender::render(built.scene, camera, settings, frame);
        row += fmt::format("| {:.2f} % | {:.3f} ", 100.0 * bench::rmse(frame.color, reference.color) / brightness, stats.seconds);
      }
      fmt::print("{}|\n", row);
    }
  }
  return 0;
}
