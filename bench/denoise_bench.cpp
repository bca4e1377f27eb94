// Prints the denoisers' figures in one run: on built-in objects in library materials under the
// paper's rig, the image's RMSE against a converged reference (percent of the object's mean) at
// several sample counts, raw, with the a-trous filter and (given --weights) with the learned
// denoiser, with the time each took (render and denoiser together); then the learned denoiser's
// inference time on a 512 x 512 frame, beside the time the render of that frame took.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include "bench_scenes.h"
#include "image_error.h"
#include "matlearn/denoising/learned_denoiser.h"
#include "matrender/render.h"

namespace {

struct Mode {
  const char* name;
  matrender::Denoising denoising;
};

// The learned denoiser's seconds on `frame` (the mean of `repeats` after one warm-up).
double inference_seconds(const matlearn::LearnedDenoiser& denoiser, const matrender::FrameBuffers& frame, int threads,
                         int repeats) {
  matrender::FrameBuffers copy = frame;
  denoiser.denoise(copy, threads);
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < repeats; ++i) {
    copy = frame;
    denoiser.denoise(copy, threads);
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / repeats;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"denoise_bench: the denoisers' error against a converged reference, raw beside filtered and learned"};
  int resolution = 192, reference_spp = 2048, threads = 2, timing_resolution = 512;
  std::vector<int> spps{4, 16, 64, 128};
  std::vector<std::string> cases{"vase:wood:1", "chair:fabric:1", "vase:metal:1"};
  std::string weights;
  app.add_option("--resolution", resolution, "image side in pixels")->capture_default_str();
  app.add_option("--reference-spp", reference_spp, "samples per pixel of the reference")->capture_default_str();
  app.add_option("--spp", spps, "sample counts compared")->capture_default_str();
  app.add_option("--cases", cases, "OBJECT:MATERIAL (a library spec)")->capture_default_str();
  app.add_option("--threads", threads, "render threads")->capture_default_str();
  app.add_option("--weights", weights, "the learned denoiser's weights (train_denoiser's); none: its column is left "
                                       "out, and its time is measured with random weights (the same cost)");
  app.add_option("--timing-resolution", timing_resolution, "side of the frame the learned denoiser is timed on")
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  torch::manual_seed(0);
  const auto learned = weights.empty() ? std::make_shared<matlearn::LearnedDenoiser>(matlearn::DenoisingUNet())
                                       : std::make_shared<matlearn::LearnedDenoiser>(std::filesystem::path(weights));
  matrender::provide_learned_denoiser(learned);
  std::vector<Mode> modes{{"raw", matrender::Denoising::Off}, {"filter", matrender::Denoising::Filter}};
  if (!weights.empty()) modes.push_back({"learned", matrender::Denoising::Learned});

  fmt::print("## Denoising: RMSE against a {} spp reference, % of the object's mean, {}x{}, {} threads\n\n",
             reference_spp, resolution, resolution, threads);
  std::string header = "| object | material | spp ", rule = "|---|---|---:";
  for (const Mode& mode : modes) {
    header += fmt::format("| {} RMSE | {} s ", mode.name, mode.name);
    rule += "|---:|---:";
  }
  fmt::print("{}|\n{}|\n", header, rule);
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
      for (const Mode& mode : modes) {
        settings.denoise = mode.denoising;
        matrender::FrameBuffers frame;
        const matrender::RenderStats stats = matrender::render(built.scene, camera, settings, frame);
        row += fmt::format("| {:.2f} % | {:.3f} ", 100.0 * bench::rmse(frame.color, reference.color) / brightness, stats.seconds);
      }
      fmt::print("{}|\n", row);
    }
  }

  // The learned denoiser's own cost on a dataset-sized frame, beside what the frame's render costs.
  matrender::BuiltScene built = bench::builtin_in_library_material("vase", "wood:1", 512);
  const matrender::Camera camera = bench::framed_grid_view(built, 1, timing_resolution);
  matrender::RenderSettings settings;
  settings.threads = threads;
  settings.samples_per_pixel = 16;
  settings.aovs = learned->guide_aovs();
  matrender::FrameBuffers frame;
  const matrender::RenderStats stats = matrender::render(built.scene, camera, settings, frame);
  fmt::print("\nlearned denoiser on a {0}x{0} frame, {1} threads: {2:.3f} s (the frame's render at {3} spp: {4:.2f} s)\n",
             timing_resolution, threads, inference_seconds(*learned, frame, threads, 5), settings.samples_per_pixel,
             stats.seconds);
  return 0;
}
