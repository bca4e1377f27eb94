// make_dataset_bench: how fast make_dataset renders the paper-scale dataset (configs/paper.yaml:
// 512 x 512, 128 spp, ambient occlusion to a 0.01 standard error) on this machine, how accurate
// those frames are against a reference of many more samples, and what that projects for the
// paper's 129,024 frames in time and disk.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "image_error.h"
#include "make_dataset/dataset_config.h"
#include "make_dataset/dataset_plan.h"
#include "make_dataset/object_renderer.h"
#include "matgeom/memory_limit.h"
#include "matgeom/threads.h"
#include "matlearn/dataset_writer.h"

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

uint64_t bytes_under(const fs::path& folder) {
  uint64_t bytes = 0;
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(folder))
    if (entry.is_regular_file()) bytes += entry.file_size();
  return bytes;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"make_dataset_bench: frames per hour at the paper's settings, their error against a high-sample "
               "reference, and the time and disk this projects for the paper-scale dataset"};
  std::string config_file = MATPREDICT_PAPER_CONFIG;
  std::vector<std::string> objects = {"chair", "vase", "sofa"};
  int views = 2, reference_frames = 2, reference_factor = 8, threads = 0;
  app.add_option("--config", config_file, "the configuration whose settings are measured")->capture_default_str();
  app.add_option("--objects", objects, "objects of the configuration to render")->capture_default_str();
  app.add_option("--views", views, "views per object, spread over the grid")->capture_default_str()->check(CLI::Range(1, 64));
  app.add_option("--reference-frames", reference_frames, "frames also rendered as a reference")
      ->capture_default_str()
      ->check(CLI::Range(0, 64));
  app.add_option("--reference-factor", reference_factor, "the reference's samples and AO trials over the frame's")
      ->capture_default_str()
      ->check(CLI::Range(2, 256));
  app.add_option("--threads", threads, "render threads, 0 every hardware thread")->capture_default_str()->check(CLI::NonNegativeNumber);
  CLI11_PARSE(app, argc, argv);
  try {
    const make_dataset::DatasetConfig config = make_dataset::load_config(config_file, {});
    const make_dataset::DatasetPlan plan = make_dataset::plan_dataset(config);
    // The reference: reference_factor times the samples and so the AO trials (the same rays per
    // sample: its error bound divided by sqrt(reference_factor)).
    const make_dataset::DatasetConfig reference = make_dataset::load_config(
        config_file, {{"render.samples", std::to_string(config.render.samples * reference_factor), "--reference-factor"},
                      {"render.ambient_occlusion.error",
                       fmt::format("{}", config.render.ambient_occlusion_error / std::sqrt(static_cast<double>(reference_factor))), "--reference-factor"}});
    const int workers = matgeom::worker_threads(threads);
    fmt::print("{}: {} frames of {}x{} at {} spp, AO error bound {}; {} threads\n", config_file, plan.frames.size(),
               config.render.width, config.render.height, config.render.samples, config.render.ambient_occlusion_error,
               workers);
    std::fflush(stdout);
    const fs::path scratch = fs::temp_directory_path() / "matpredict_make_dataset_bench";
    fs::remove_all(scratch);

    double render_seconds = 0.0, write_seconds = 0.0, setup_seconds = 0.0;
    size_t frames = 0, referenced = 0;
    std::vector<double> image_errors, ao_errors;
    for (const std::string& name : objects) {
      const auto it = std::find_if(config.objects.begin(), config.objects.end(),
                                   [&](const make_dataset::ObjectConfig& o) { return o.name == name; });
      if (it == config.objects.end()) throw std::runtime_error("--objects: the configuration has no object " + name);
      const size_t object = static_cast<size_t>(it - config.objects.begin());
      const size_t variant = object % plan.variants[object].size();
      const Clock::time_point setup = Clock::now();
      make_dataset::ObjectRenderer renderer(config, object);
      renderer.select_variant(plan.variants[object][variant]);
      setup_seconds += seconds_since(setup);
      fmt::print("{}: set up in {:.1f} s\n", name, seconds_since(setup));
      std::unique_ptr<make_dataset::ObjectRenderer> reference_renderer;
      for (int k = 0; k < views; ++k) {
        const size_t view = views == 1 ? plan.views / 2 : static_cast<size_t>(k) * (plan.views - 1) / static_cast<size_t>(views - 1);
        const uint32_t seed = make_dataset::frame_seed(config.seed, {object, variant, view});
        matlearn::FrameMaps maps;
        const Clock::time_point start = Clock::now();
        matrender::RenderStats stats;
        renderer.render(view, seed, workers, nullptr, maps, &stats);
        const double seconds = seconds_since(start);
        const Clock::time_point written = Clock::now();
        matlearn::write_frame_maps(scratch / name, make_dataset::view_stem(plan, view), maps);
        write_seconds += seconds_since(written);
        render_seconds += seconds;
        ++frames;
        std::string error;
        if (static_cast<int>(referenced) < reference_frames) {
          if (!reference_renderer) {
            reference_renderer = std::make_unique<make_dataset::ObjectRenderer>(reference, object);
            reference_renderer->select_variant(plan.variants[object][variant]);
          }
          matlearn::FrameMaps truth;
          reference_renderer->render(view, seed + 1, workers, nullptr, truth);
          // E|a - r|^2 = var(a) (1 + 1/factor): the reference's own noise taken out.
          const double own = std::sqrt(1.0 + 1.0 / reference_factor);
          const double brightness = bench::mean(truth.color) / std::max(bench::mean(truth.coverage), 1e-9);
          image_errors.push_back(bench::rmse(maps.color, truth.color) / own / brightness);
          ao_errors.push_back(bench::covered_rmse(maps.ambient_occlusion, truth.ambient_occlusion, maps.coverage, truth.coverage) / own);
          error = fmt::format("; against the reference: image RMSE {:.2f} % of the object's mean, AO RMSE {:.4f}",
                              100.0 * image_errors.back(), ao_errors.back());
          ++referenced;
        }
        fmt::print("{} variant {} view {}: {:.1f} s, {:.1f} rays per sample, AO standard error estimated {:.4f} "
                   "(largest {:.4f}){}\n",
                   name, variant, view, seconds, static_cast<double>(stats.rays) / static_cast<double>(stats.camera_samples),
                   stats.occlusion_rms_standard_error, stats.occlusion_max_standard_error, error);
        std::fflush(stdout);
      }
    }
    const double per_frame = (render_seconds + write_seconds) / static_cast<double>(frames);
    const double bytes_per_frame = static_cast<double>(bytes_under(scratch)) / static_cast<double>(frames);
    const double paper = static_cast<double>(plan.frames.size());
    fmt::print("\nframes: {:.1f} s each ({:.2f} s of it writing): {:.0f} frames/hour on {} threads\n", per_frame,
               write_seconds / frames, 3600.0 / per_frame, workers);
    if (!image_errors.empty())
      fmt::print("error against {}x the samples: image RMSE {:.2f} % of the object's mean (worst {:.2f} %), AO RMSE "
                 "{:.4f} (worst {:.4f}; bound {})\n",
                 reference_factor, 100.0 * bench::mean(std::vector<float>(image_errors.begin(), image_errors.end())),
                 100.0 * *std::max_element(image_errors.begin(), image_errors.end()),
                 bench::mean(std::vector<float>(ao_errors.begin(), ao_errors.end())),
                 *std::max_element(ao_errors.begin(), ao_errors.end()), config.render.ambient_occlusion_error);
    fmt::print("object set-up (scene, BVH, one {}-texel material): {:.1f} s per object and variant\n",
               config.render.material_resolution, setup_seconds / objects.size());
    fmt::print("projected for {:.0f} frames: {:.0f} hours ({:.1f} days) on {} threads, {:.0f} machine-hours; {} on "
               "disk ({} per frame)\n",
               paper, paper * per_frame / 3600.0, paper * per_frame / 86400.0, workers, paper * per_frame / 3600.0,
               matgeom::byte_size_text(paper * bytes_per_frame), matgeom::byte_size_text(bytes_per_frame));
    fs::remove_all(scratch);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "make_dataset_bench: %s\n", e.what());
    return 1;
  }
}
