// make_dataset_bench: how fast make_dataset renders the paper-scale dataset (configs/paper.yaml:
// 512 x 512, 128 spp, ambient occlusion to a 0.01 standard error) on this machine, how accurate
// those frames are against a reference of many more samples, and what that projects for the
// paper's 129,024 frames in time and disk; side by side, on the same frames in one run, for each
// mode of rendering (fixed samples, adaptive sampling, adaptive sampling and the denoiser).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
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

// A way of rendering the configuration: its name and the keys it overrides.
struct Mode {
  std::string name;
  std::vector<make_dataset::Override> overrides;
};

// "KEY=VALUE", given with `option`.
make_dataset::Override parse_override(const std::string& text, const std::string& option) {
  const size_t equals = text.find('=');
  if (equals == std::string::npos) throw std::runtime_error(option + ": expected KEY=VALUE, got " + text);
  return {text.substr(0, equals), text.substr(equals + 1), option};
}

// "NAME" or "NAME:KEY=VALUE,KEY=VALUE".
Mode parse_mode(const std::string& text) {
  Mode mode;
  const size_t colon = text.find(':');
  mode.name = text.substr(0, colon);
  for (size_t start = colon; start != std::string::npos && start < text.size();) {
    const size_t comma = text.find(',', start + 1);
    mode.overrides.push_back(parse_override(text.substr(start + 1, comma - start - 1), "--mode " + mode.name));
    start = comma;
  }
  return mode;
}

// What one mode's frames took and how far they are from the reference.
struct ModeFigures {
  double render_seconds = 0.0, write_seconds = 0.0, samples = 0.0;
  size_t frames = 0;
  uint64_t bytes = 0;
  std::vector<double> image_errors, ao_errors;
};

double worst(const std::vector<double>& values) { return *std::max_element(values.begin(), values.end()); }
double average(const std::vector<double>& values) {
  double sum = 0.0;
  for (const double v : values) sum += v;
  return sum / static_cast<double>(values.size());
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"make_dataset_bench: frames per hour at the paper's settings, their error against a high-sample "
               "reference, and the time and disk this projects for the paper-scale dataset, for each mode of "
               "rendering side by side"};
  std::string config_file = MATPREDICT_PAPER_CONFIG;
  std::vector<std::string> objects = {"chair", "vase", "sofa"};
  std::vector<std::string> mode_texts = {"fixed", "adaptive:render.noise_threshold=0.01",
                                         "adaptive+denoise:render.noise_threshold=0.01,render.denoise=true"};
  std::vector<std::string> set_texts;
  int views = 2, reference_frames = 2, reference_factor = 8, threads = 0;
  app.add_option("--config", config_file, "the configuration whose settings are measured")->capture_default_str();
  app.add_option("--set", set_texts, "KEY=VALUE: set a key of the configuration for every mode and the reference");
  app.add_option("--objects", objects, "objects of the configuration to render, NAME or NAME:VARIANT (default: the "
                                       "object's index modulo its variants)")
      ->capture_default_str();
  app.add_option("--mode", mode_texts, "NAME or NAME:KEY=VALUE,...: a way of rendering, compared on the same frames")
      ->capture_default_str();
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
    std::vector<make_dataset::Override> sets;
    for (const std::string& text : set_texts) sets.push_back(parse_override(text, "--set"));
    std::vector<Mode> modes;
    for (const std::string& text : mode_texts) modes.push_back(parse_mode(text));
    std::vector<make_dataset::DatasetConfig> configs;
    for (const Mode& mode : modes) {
      std::vector<make_dataset::Override> overrides = sets;
      overrides.insert(overrides.end(), mode.overrides.begin(), mode.overrides.end());
      configs.push_back(make_dataset::load_config(config_file, overrides));
    }
    const make_dataset::DatasetConfig config = make_dataset::load_config(config_file, sets);
    const make_dataset::DatasetPlan plan = make_dataset::plan_dataset(config);
    // The reference: the configuration's fixed samples times reference_factor, and its AO error
    // bound over sqrt(reference_factor).
    std::vector<make_dataset::Override> reference_overrides = sets;
    reference_overrides.push_back(
        {"render.samples", std::to_string(config.render.samples * reference_factor), "--reference-factor"});
    reference_overrides.push_back({"render.ambient_occlusion.error",
                                   fmt::format("{}", config.render.ambient_occlusion_error /
                                                         std::sqrt(static_cast<double>(reference_factor))),
                                   "--reference-factor"});
    const make_dataset::DatasetConfig reference = make_dataset::load_config(config_file, reference_overrides);
    const int workers = matgeom::worker_threads(threads);
    fmt::print("{}: {} frames of {}x{} at {} spp, AO error bound {}; {} threads; modes:", config_file, plan.frames.size(),
               config.render.width, config.render.height, config.render.samples, config.render.ambient_occlusion_error,
               workers);
    for (const std::string& text : mode_texts) fmt::print(" {}", text);
    fmt::print("\n");
    std::fflush(stdout);
    const fs::path scratch = fs::temp_directory_path() / "matpredict_make_dataset_bench";
    fs::remove_all(scratch);

    std::vector<ModeFigures> figures(modes.size());
    double setup_seconds = 0.0;
    size_t referenced = 0;
    for (const std::string& spec : objects) {
      const std::string name = spec.substr(0, spec.find(':'));
      const auto it = std::find_if(config.objects.begin(), config.objects.end(),
                                   [&](const make_dataset::ObjectConfig& o) { return o.name == name; });
      if (it == config.objects.end()) throw std::runtime_error("--objects: the configuration has no object " + name);
      const size_t object = static_cast<size_t>(it - config.objects.begin());
      const std::string given = spec.find(':') == std::string::npos ? "" : spec.substr(spec.find(':') + 1);
      if (!given.empty() && given.find_first_not_of("0123456789") != std::string::npos)
        throw std::runtime_error("--objects: " + spec + ": the variant is a whole number");
      const size_t variant = given.empty() ? object % plan.variants[object].size() : std::stoul(given);
      if (variant >= plan.variants[object].size())
        throw std::runtime_error("--objects: " + name + " has " + std::to_string(plan.variants[object].size()) + " variants");
      const Clock::time_point setup = Clock::now();
      std::vector<std::unique_ptr<make_dataset::ObjectRenderer>> renderers;
      for (const make_dataset::DatasetConfig& mode_config : configs) {
        renderers.push_back(std::make_unique<make_dataset::ObjectRenderer>(mode_config, object));
        renderers.back()->select_variant(plan.variants[object][variant]);
      }
      setup_seconds += seconds_since(setup) / static_cast<double>(modes.size());
      fmt::print("{} variant {} ({}): set up in {:.1f} s a mode\n", name, variant,
                 renderers.front()->slot_materials().front().material, seconds_since(setup) / modes.size());
      std::unique_ptr<make_dataset::ObjectRenderer> reference_renderer;
      for (int k = 0; k < views; ++k) {
        const size_t view = views == 1 ? plan.views / 2 : static_cast<size_t>(k) * (plan.views - 1) / static_cast<size_t>(views - 1);
        const uint32_t seed = make_dataset::frame_seed(config.seed, {object, variant, view});
        std::optional<matlearn::FrameMaps> truth;
        if (static_cast<int>(referenced) < reference_frames) {
          if (!reference_renderer) {
            reference_renderer = std::make_unique<make_dataset::ObjectRenderer>(reference, object);
            reference_renderer->select_variant(plan.variants[object][variant]);
          }
          truth.emplace();
          reference_renderer->render(view, seed + 1, workers, nullptr, *truth);
          ++referenced;
        }
        for (size_t m = 0; m < modes.size(); ++m) {
          matlearn::FrameMaps maps;
          matrender::RenderStats stats;
          const Clock::time_point start = Clock::now();
          renderers[m]->render(view, seed, workers, nullptr, maps, &stats);
          const double seconds = seconds_since(start);
          const Clock::time_point written = Clock::now();
          matlearn::write_frame_maps(scratch / modes[m].name / name, make_dataset::view_stem(plan, view), maps);
          ModeFigures& f = figures[m];
          f.write_seconds += seconds_since(written);
          f.render_seconds += seconds;
          f.samples += static_cast<double>(stats.camera_samples) / (static_cast<double>(maps.width) * maps.height);
          ++f.frames;
          std::string error;
          if (truth) {
            // E|a - r|^2 = var(a) (1 + 1/factor) for a fixed-sample frame: the reference's own noise
            // taken out (for the other modes an approximation).
            const double own = std::sqrt(1.0 + 1.0 / reference_factor);
            const double brightness = bench::mean(truth->color) / std::max(bench::mean(truth->coverage), 1e-9);
            f.image_errors.push_back(bench::rmse(maps.color, truth->color) / own / brightness);
            f.ao_errors.push_back(
                bench::covered_rmse(maps.ambient_occlusion, truth->ambient_occlusion, maps.coverage, truth->coverage) / own);
            error = fmt::format("; image RMSE {:.2f} % of the object's mean, AO RMSE {:.4f}", 100.0 * f.image_errors.back(),
                                f.ao_errors.back());
          }
          fmt::print("{} view {} {}: {:.1f} s, {:.0f} samples a pixel, {:.1f} rays a sample, AO error estimated {:.4f}{}\n",
                     name, view, modes[m].name, seconds, static_cast<double>(stats.camera_samples) / (maps.width * maps.height),
                     static_cast<double>(stats.rays) / static_cast<double>(stats.camera_samples),
                     stats.occlusion_rms_standard_error, error);
          std::fflush(stdout);
        }
      }
    }
    const double paper = static_cast<double>(plan.frames.size());
    fmt::print("\nobject set-up (scene, BVH, one {}-texel material): {:.1f} s per object and variant\n\n",
               config.render.material_resolution, setup_seconds / objects.size());
    fmt::print("| mode | s per frame | frames per hour | samples a pixel | image RMSE, % of the object's mean (worst) | AO RMSE "
               "(worst) | paper scale: hours on {} threads | on a 100-task array | disk |\n"
               "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n",
               workers);
    for (size_t m = 0; m < modes.size(); ++m) {
      const ModeFigures& f = figures[m];
      const double per_frame = (f.render_seconds + f.write_seconds) / static_cast<double>(f.frames);
      const double bytes = static_cast<double>(bytes_under(scratch / modes[m].name)) / static_cast<double>(f.frames);
      const std::string errors =
          f.image_errors.empty() ? "| - | -"
                                 : fmt::format("| {:.2f} ({:.2f}) | {:.4f} ({:.4f})", 100.0 * average(f.image_errors),
                                               100.0 * worst(f.image_errors), average(f.ao_errors), worst(f.ao_errors));
      fmt::print("| {} | {:.1f} | {:.0f} | {:.0f} {} | {:.0f} | {:.1f} | {} |\n", modes[m].name, per_frame, 3600.0 / per_frame,
                 f.samples / static_cast<double>(f.frames), errors, paper * per_frame / 3600.0,
                 paper * per_frame / 3600.0 / 100.0, matgeom::byte_size_text(paper * bytes));
    }
    fs::remove_all(scratch);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "make_dataset_bench: %s\n", e.what());
    return 1;
  }
}
