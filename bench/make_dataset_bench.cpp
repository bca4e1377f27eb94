// make_dataset_bench: how fast make_dataset renders the paper-scale dataset (configs/paper.yaml:
// 512 x 512, 128 spp, ambient occlusion to a 0.01 standard error) on this machine, how accurate
// those frames are against a reference of many more samples, and what that projects for the
// paper's 129,024 frames in time and disk; side by side, on the same frames in one run, for each
// way of rendering (fixed samples, adaptive sampling, adaptive sampling and the denoiser, each
// swept over a series of settings) and, with --cycles, for Blender 3.4 Cycles; and from those
// series, the time each needs to reach the same image error, and Cycles' time over ours there.
// The errors compared at: --target-error on every frame; on each frame, the error of the point
// that samples as the configuration does (fixed 128 spp for paper.yaml); and each of Cycles'.
//
// Options (--help lists them with their defaults):
//   --config FILE, --set KEY=VALUE   the configuration measured, and keys set for everything
//   --objects NAME[:VARIANT] ...     the configuration's objects, each in one variant
//   --views N                        views per object, spread over the grid
//   --mode NAME[:KEY=VALUE,...] ...  a way of rendering; one VALUE may list several, v1|v2|...,
//                                    which makes the mode a series of one point per value, listed
//                                    by increasing cost
//   --reference-frames N, --reference-factor F
//                                    frames also rendered as a reference, at F x the samples
//   --target-error PERCENT           an image error the times at equal error and the
//                                    paper-scale projection are read at
//   --cycles, --blender PATH, --cycles-thresholds T ..., --cycles-max-samples N
//                                    Blender 3.4 Cycles on the referenced frames, adaptive
//                                    sampling at each noise threshold
//   --images DIR                     the converged references as PNGs, to look at
//   --lighting NAME=YAML ...         a `lights` value: everything above is measured under each
//                                    lighting in turn (references included), and a last table
//                                    gives each one's render seconds to the error the first
//                                    one's frames have as configured, and their ratio to it
//   --surroundings NAME=YAML ...     the same for `surroundings` values (none, a floor, a room,
//                                    distractors): what surroundings cost at equal error, the
//                                    image error then taken on the object's pixels alone
//   --threads N
//
// Image error is the RMSE over the image (every pixel and channel, linear radiance) against the
// renderer's own converged reference, over the object's mean brightness in that reference (its
// mean over the pixels our reference covers), so exposure cancels; the reference's own noise is
// taken out. Cycles gets the frame as a Blender user builds it: the object in the variant's
// materials written as glTF (matgeom::write_gltf) and brought in by Blender's own glTF importer,
// which makes its own node setups; the scene's lamps and background; the view's camera; the
// configuration's size and bounces; and Cycles' defaults otherwise (as shaders_ref/cycles_render.py
// sets them for "blender_defaults"): adaptive sampling on at each threshold with Min Samples 0
// (automatic), no denoiser (Debian's build has none). Its reference is the same scene at fixed
// samples. Times: ours, the render call (the BVH is built once per object, in the set-up);
// Cycles', its render call, which syncs the scene and builds its BVH every call; Blender's
// start-up and the import are in neither. Needs Debian's `blender` (3.4) only with --cycles.
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
#include <utility>
#include <variant>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "image_error.h"
#include "matbase/image/image_writing.h"
#include "matbase/memory_limit.h"
#include "matbase/threads.h"
#include "matdataset/format/dataset_writer.h"
#include "matdataset/maker/dataset_config.h"
#include "matdataset/maker/dataset_plan.h"
#include "matdataset/maker/object_renderer.h"
#include "matgeom/io/gltf/gltf_writer.h"
#include "shaders_ref/cycles_reference.h"

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
  std::vector<matdataset::Override> overrides;
};

// Ways of rendering that differ in one key's value: the points of one error-against-time curve.
struct Series {
  std::string name;
  std::vector<Mode> points;
};

// "KEY=VALUE", given with `option`.
matdataset::Override parse_override(const std::string& text, const std::string& option) {
  const size_t equals = text.find('=');
  if (equals == std::string::npos) throw std::runtime_error(option + ": expected KEY=VALUE, got " + text);
  return {text.substr(0, equals), text.substr(equals + 1), option};
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  for (size_t start = 0;;) {
    const size_t end = text.find(separator, start);
    parts.push_back(text.substr(start, end - start));
    if (end == std::string::npos) return parts;
    start = end + 1;
  }
}

// "NAME" or "NAME:KEY=VALUE,KEY=VALUE", where one VALUE may be "v1|v2|...": a point per value,
// named "NAME KEY=v".
Series parse_series(const std::string& text) {
  Series series;
  const size_t colon = text.find(':');
  series.name = text.substr(0, colon);
  const std::string option = "--mode " + series.name;
  std::vector<matdataset::Override> overrides;
  if (colon != std::string::npos)
    for (const std::string& item : split(text.substr(colon + 1), ','))
      overrides.push_back(parse_override(item, option));
  const auto listed = [](const matdataset::Override& o) { return o.value.find('|') != std::string::npos; };
  const auto swept = std::find_if(overrides.begin(), overrides.end(), listed);
  if (swept == overrides.end()) return {series.name, {{series.name, overrides}}};
  if (std::count_if(overrides.begin(), overrides.end(), listed) > 1)
    throw std::runtime_error(option + ": only one key may list several values");
  for (const std::string& value : split(swept->value, '|')) {
    Mode point{series.name + " " + swept->key + "=" + value, overrides};
    point.overrides[static_cast<size_t>(swept - overrides.begin())].value = value;
    series.points.push_back(std::move(point));
  }
  return series;
}

// What one way of rendering's frames took and how far they are from the reference.
struct ModeFigures {
  double render_seconds = 0.0, write_seconds = 0.0, samples = 0.0;
  size_t frames = 0;
  // On the referenced frames, in order: render seconds, image error, AO error.
  std::vector<double> referenced_seconds, image_errors, ao_errors;
};

double worst(const std::vector<double>& values) { return *std::max_element(values.begin(), values.end()); }
double average(const std::vector<double>& values) {
  double sum = 0.0;
  for (const double v : values) sum += v;
  return sum / static_cast<double>(values.size());
}

// The object's mean brightness: the image's mean over the covered fraction of the frame.
double object_mean(const std::vector<float>& color, const std::vector<float>& coverage) {
  return bench::mean(color) / std::max(bench::mean(coverage), 1e-9);
}

// RMSE against the reference over the object's mean brightness in the reference, the
// reference's own noise taken out: E|a - r|^2 = var(a) (1 + 1/factor) for a fixed-sample frame
// (for adaptive sampling and the denoiser an approximation).
double image_error(const std::vector<float>& image, const std::vector<float>& reference, double reference_object_mean,
                   int reference_factor) {
  return bench::rmse(image, reference) / std::sqrt(1.0 + 1.0 / reference_factor) / reference_object_mean;
}

// An object of the configuration, and the variant "NAME:VARIANT" gives (else the object's index
// modulo its variants).
std::pair<size_t, size_t> object_and_variant(const std::string& spec, const matdataset::DatasetConfig& config,
                                             const matdataset::DatasetPlan& plan) {
  const std::string name = spec.substr(0, spec.find(':'));
  const auto it = std::find_if(config.objects.begin(), config.objects.end(),
                               [&](const matdataset::ObjectConfig& o) { return o.name == name; });
  if (it == config.objects.end()) throw std::runtime_error("--objects: the configuration has no object " + name);
  const size_t object = static_cast<size_t>(it - config.objects.begin());
  const std::string given = spec.find(':') == std::string::npos ? "" : spec.substr(spec.find(':') + 1);
  if (!given.empty() && given.find_first_not_of("0123456789") != std::string::npos)
    throw std::runtime_error("--objects: " + spec + ": the variant is a whole number");
  const size_t variant = given.empty() ? object % plan.variants[object].size() : std::stoul(given);
  if (variant >= plan.variants[object].size())
    throw std::runtime_error("--objects: " + name + " has " + std::to_string(plan.variants[object].size()) +
                             " variants");
  return {object, variant};
}

// `views` views spread evenly over the grid's, the middle one when one.
std::vector<size_t> spread_views(int views, size_t grid_views) {
  std::vector<size_t> spread;
  for (int k = 0; k < views; ++k)
    spread.push_back(views == 1 ? grid_views / 2
                                : static_cast<size_t>(k) * (grid_views - 1) / static_cast<size_t>(views - 1));
  return spread;
}

struct CyclesOptions {
  bool enabled = false;
  std::string blender = "blender";
  std::vector<double> thresholds = {0.1, 0.05, 0.02, 0.01};
  int max_samples = 512;
};

// The frame as a Blender user builds it (see the top of this file).
shaders_ref::CyclesScene cycles_scene(const matdataset::ObjectRenderer& renderer, size_t view,
                                      const std::string& gltf, const matdataset::RenderConfig& r) {
  shaders_ref::CyclesScene scene;
  scene.gltf_path = gltf;
  scene.lamps = renderer.scene().lamps();
  const auto* background = std::get_if<glm::vec3>(&renderer.scene().background());
  if (!background) throw std::runtime_error("--cycles: the scene's environment map is not passed to Blender");
  scene.background = *background;
  scene.camera = renderer.view_camera(view);
  scene.bounces = {r.settings.max_bounces, r.settings.max_diffuse_bounces, r.settings.max_glossy_bounces,
                   r.settings.max_transmission_bounces};
  scene.settings = shaders_ref::CyclesSettings::BlenderDefaults;
  return scene;
}

// Cycles' reference at fixed samples first (the session's first render also reads the images),
// then one sample (what a render call costs before sampling: scene sync, BVH, textures handed to
// Cycles, every call), then a render per noise threshold.
std::vector<shaders_ref::CyclesRender> render_with_cycles(const shaders_ref::CyclesScene& scene,
                                                          const CyclesOptions& options, int reference_samples,
                                                          int threads, const fs::path& folder) {
  std::vector<shaders_ref::CyclesRender> renders = {{reference_samples, 1}, {1, 0}};
  for (const double threshold : options.thresholds) renders.push_back({options.max_samples, 0, threshold});
  shaders_ref::render_with_cycles(scene, renders, threads, folder.string(), options.blender);
  return renders;
}

// What every measurement of a run shares.
struct Run {
  const matdataset::DatasetPlan& plan;
  int workers, reference_factor, reference_samples;
  fs::path scratch;    // frames are written here, as make_dataset writes them
  std::string images;  // the references go here as PNGs; empty: nowhere
  // The image error on the object's pixels (the reference's label) alone, as surroundings are
  // compared: their floor's and walls' noise is not the object's.
  bool object_pixels = false;
};

// A view of an object, its seed, and its reference when it has one.
struct Frame {
  std::string object;
  size_t view;
  uint32_t seed;
  std::optional<matdataset::FrameMaps> truth;
};

void render_reference(const Run& run, matdataset::ObjectRenderer& renderer, Frame& frame) {
  const Clock::time_point start = Clock::now();
  renderer.render(frame.view, frame.seed + 1, run.workers, nullptr, frame.truth.emplace());
  fmt::print("{} view {} reference, {} spp: {:.2f} s\n", frame.object, frame.view, run.reference_samples,
             seconds_since(start));
  if (!run.images.empty())
    matbase::write_display_png(fmt::format("{}/{}_view{}_ours.png", run.images, frame.object, frame.view),
                               frame.truth->width, frame.truth->height, frame.truth->color.data(), nullptr,
                               frame.truth->exposure_stops);
}

// Renders and writes the frames as make_dataset does, into `f`.
void measure_mode(const Run& run, matdataset::ObjectRenderer& renderer, const std::string& mode,
                  const std::vector<Frame>& frames, ModeFigures& f) {
  for (const Frame& frame : frames) {
    matdataset::FrameMaps maps;
    matrender::RenderStats stats;
    const Clock::time_point start = Clock::now();
    renderer.render(frame.view, frame.seed, run.workers, nullptr, maps, &stats);
    const double seconds = seconds_since(start);
    const Clock::time_point written = Clock::now();
    matdataset::write_frame_maps(run.scratch / mode / frame.object, matdataset::view_stem(run.plan, frame.view), maps);
    f.write_seconds += seconds_since(written);
    f.render_seconds += seconds;
    f.samples += static_cast<double>(stats.camera_samples) / (static_cast<double>(maps.width) * maps.height);
    ++f.frames;
    std::string error;
    if (const std::optional<matdataset::FrameMaps>& truth = frame.truth) {
      // The reference's own noise taken out of the AO error as of the image's.
      const double own = std::sqrt(1.0 + 1.0 / run.reference_factor);
      f.referenced_seconds.push_back(seconds);
      f.image_errors.push_back(
          run.object_pixels
              ? bench::masked_rmse(maps.color, truth->color, truth->label, 3) /
                    std::sqrt(1.0 + 1.0 / run.reference_factor) / bench::masked_mean(truth->color, truth->label, 3)
              : image_error(maps.color, truth->color, object_mean(truth->color, truth->coverage), run.reference_factor));
      f.ao_errors.push_back(
          bench::covered_rmse(maps.ambient_occlusion, truth->ambient_occlusion, maps.coverage, truth->coverage) / own);
      error = fmt::format("; image RMSE {:.2f} % of the object's mean{}, AO RMSE {:.4f}", 100.0 * f.image_errors.back(),
                          run.object_pixels ? " on its pixels" : "", f.ao_errors.back());
    }
    fmt::print("{} view {} {}: {:.2f} s, {:.0f} samples a pixel, {:.1f} rays a sample, AO error estimated {:.4f}{}\n",
               frame.object, frame.view, mode, seconds,
               static_cast<double>(stats.camera_samples) / (maps.width * maps.height),
               static_cast<double>(stats.rays) / static_cast<double>(stats.camera_samples),
               stats.occlusion_rms_standard_error, error);
    std::fflush(stdout);
  }
}

// Renders the referenced frames with Cycles (a Blender run each: its reference, one sample, a
// render per threshold), their figures into `figures` (a threshold each). The object goes to
// Blender as glTF, written once.
void measure_cycles(const Run& run, const CyclesOptions& cycles, const matdataset::ObjectRenderer& renderer,
                    const matdataset::RenderConfig& r, const std::vector<Frame>& frames,
                    std::vector<ModeFigures>& figures) {
  const fs::path folder = run.scratch / "cycles" / frames.front().object;
  fs::create_directories(folder);
  const std::string gltf = (folder / "object.glb").string();
  matgeom::write_gltf(renderer.variant_asset(), gltf);
  for (const Frame& frame : frames) {
    if (!frame.truth) continue;
    const matdataset::FrameMaps& truth = *frame.truth;
    const std::vector<shaders_ref::CyclesRender> renders =
        render_with_cycles(cycles_scene(renderer, frame.view, gltf, r), cycles, run.reference_samples, run.workers,
                           folder / ("view" + std::to_string(frame.view)));
    const std::vector<float> cycles_truth =
        shaders_ref::read_rgb_exr(renders.front().exr_path, truth.width, truth.height);
    // Cycles' object covers what ours does (the same mesh and camera): our reference's coverage.
    const double cycles_mean = object_mean(cycles_truth, truth.coverage),
                 ours_mean = object_mean(truth.color, truth.coverage);
    fmt::print(
        "{} view {} Cycles' reference, {} spp: {:.2f} s (a render call of 1 sample: {:.2f} s); its object mean "
        "over ours {:.3f}, their difference RMSE {:.1f} % of ours\n",
        frame.object, frame.view, run.reference_samples, renders[0].seconds, renders[1].seconds,
        cycles_mean / ours_mean, 100.0 * bench::rmse(cycles_truth, truth.color) / ours_mean);
    if (!run.images.empty())
      matbase::write_display_png(fmt::format("{}/{}_view{}_cycles.png", run.images, frame.object, frame.view),
                                 truth.width, truth.height, cycles_truth.data(), nullptr, truth.exposure_stops);
    for (size_t t = 0; t < cycles.thresholds.size(); ++t) {
      const shaders_ref::CyclesRender& render = renders[t + 2];
      ModeFigures& f = figures[t];
      f.render_seconds += render.seconds;
      f.referenced_seconds.push_back(render.seconds);
      ++f.frames;
      f.image_errors.push_back(image_error(shaders_ref::read_rgb_exr(render.exr_path, truth.width, truth.height),
                                           cycles_truth, cycles_mean, run.reference_factor));
      fmt::print("{} view {} Cycles threshold {}: {:.2f} s; image RMSE {:.2f} % of the object's mean\n", frame.object,
                 frame.view, cycles.thresholds[t], render.seconds, 100.0 * f.image_errors.back());
    }
    std::fflush(stdout);
  }
}

// When a curve reaches an error: interpolated between its points, or at most its first point's
// seconds when that one is already there; none beyond its last point (no extrapolation).
struct Reach {
  double seconds = 0.0;
  bool at_most = false;
};

std::optional<Reach> reach(const bench::Curve& curve, double error) {
  const double seconds = bench::seconds_to_reach(curve, error);
  if (std::isnan(seconds)) return std::nullopt;
  return Reach{seconds, curve.error.front() < error};
}

std::string reach_text(const std::optional<Reach>& r, double scale = 1.0) {
  if (!r) return "not reached";
  return fmt::format("{}{:.3g}", r->at_most ? "≤ " : "", r->seconds * scale);
}

// Cycles' time over ours at equal error; a bound when one of them is.
std::string ratio_text(const std::optional<Reach>& cycles, const std::optional<Reach>& ours) {
  if (!cycles || !ours || (cycles->at_most && ours->at_most)) return "-";
  return fmt::format("{}{:.2f}", ours->at_most ? "≥ " : cycles->at_most ? "≤ " : "", cycles->seconds / ours->seconds);
}

// Whether two configurations sample a frame alike: the point that renders as the configuration does.
bool same_sampling(const matdataset::RenderConfig& a, const matdataset::RenderConfig& b) {
  const matrender::RenderSettings& s = a.settings;
  const matrender::RenderSettings& t = b.settings;
  return s.samples_per_pixel == t.samples_per_pixel && s.noise_threshold == t.noise_threshold &&
         s.min_samples == t.min_samples && s.denoise == t.denoise;
}

// A way of rendering over its points, on each referenced frame: render seconds against image
// error. Each frame has its own curve, since an error one material reaches early another may
// never reach; the points keep the order they are given in, by increasing cost (timings of
// cheap frames are too noisy to order them).
struct SeriesCurves {
  std::string name;
  std::vector<bench::Curve> frames;
};

SeriesCurves series_curves(const std::string& name, const std::vector<const ModeFigures*>& points) {
  SeriesCurves series{name, std::vector<bench::Curve>(points.front()->image_errors.size())};
  for (size_t f = 0; f < series.frames.size(); ++f)
    for (const ModeFigures* point : points) {
      series.frames[f].seconds.push_back(point->referenced_seconds[f]);
      series.frames[f].error.push_back(point->image_errors[f]);
    }
  return series;
}

// An image error on each referenced frame, at which the series are compared.
struct ErrorLevel {
  std::string label;
  std::vector<double> errors;
};

// The mean over the frames of the seconds a frame needs to reach the level's error: none when a
// frame never gets there, at most when a frame's cheapest point is already there.
std::optional<Reach> mean_reach(const SeriesCurves& series, const ErrorLevel& level) {
  Reach mean{0.0, false};
  for (size_t f = 0; f < series.frames.size(); ++f) {
    const std::optional<Reach> r = reach(series.frames[f], level.errors[f]);
    if (!r) return std::nullopt;
    mean.seconds += r->seconds / static_cast<double>(series.frames.size());
    mean.at_most = mean.at_most || r->at_most;
  }
  return mean;
}

// Each point's figures, ours and Cycles': time, error, and what they project for the paper.
void print_points(const std::vector<Mode>& modes, const std::vector<ModeFigures>& figures, const fs::path& scratch,
                  const std::vector<double>& cycles_thresholds, const std::vector<ModeFigures>& cycles_figures,
                  double paper, int workers) {
  fmt::print(
      "| mode | s per frame | frames per hour | samples a pixel | image RMSE, % of the object's mean (worst) | AO RMSE "
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
    fmt::print("| {} | {:.2f} | {:.0f} | {:.0f} {} | {:.0f} | {:.1f} | {} |\n", modes[m].name, per_frame,
               3600.0 / per_frame, f.samples / static_cast<double>(f.frames), errors, paper * per_frame / 3600.0,
               paper * per_frame / 3600.0 / 100.0, matbase::byte_size_text(paper * bytes));
  }
  for (size_t t = 0; t < cycles_figures.size() && cycles_figures[t].frames > 0; ++t) {
    const ModeFigures& f = cycles_figures[t];
    const double per_frame = f.render_seconds / static_cast<double>(f.frames);
    fmt::print("| Cycles 3.4 threshold {} | {:.2f} | {:.0f} | - | {:.2f} ({:.2f}) | - | {:.0f} | {:.1f} | - |\n",
               cycles_thresholds[t], per_frame, 3600.0 / per_frame, 100.0 * average(f.image_errors),
               100.0 * worst(f.image_errors), paper * per_frame / 3600.0, paper * per_frame / 3600.0 / 100.0);
  }
  fmt::print(
      "\ns per frame: ours, rendering and writing the frame's maps{}.\n",
      cycles_figures.empty() || cycles_figures.front().frames == 0 ? "" : "; Cycles, its render call, writing one EXR");
}

// Render seconds a frame (only, so that ours and Cycles' compare) each series needs to reach
// each level, with Cycles' time over ours.
void print_equal_error(const std::vector<SeriesCurves>& series, const std::optional<SeriesCurves>& cycles,
                       const std::vector<ErrorLevel>& levels) {
  fmt::print(
      "\nRender seconds a frame to reach each level of image error on every referenced frame (mean over "
      "the frames; each frame interpolated log-log between a series' points; \"≤\": a frame's cheapest point "
      "is already there)\n\n| image RMSE, % of the object's mean |");
  std::string rule = "|---|";
  if (cycles) fmt::print(" Cycles 3.4 |"), rule += "---:|";
  for (const SeriesCurves& s : series) {
    fmt::print(" {} |", s.name), rule += "---:|";
    if (cycles) fmt::print(" Cycles / {} |", s.name), rule += "---:|";
  }
  fmt::print("\n{}\n", rule);
  for (const ErrorLevel& level : levels) {
    fmt::print("| {} |", level.label);
    std::optional<Reach> theirs;
    if (cycles) theirs = mean_reach(*cycles, level), fmt::print(" {} |", reach_text(theirs));
    for (const SeriesCurves& s : series) {
      const std::optional<Reach> ours = mean_reach(s, level);
      fmt::print(" {} |", reach_text(ours));
      if (cycles) fmt::print(" {} |", ratio_text(theirs, ours));
    }
    fmt::print("\n");
  }
}

// What the seconds a frame at each level (the target, as configured) project for the paper's frames.
void print_projection(const std::vector<SeriesCurves>& series, const std::vector<ErrorLevel>& levels, double paper,
                      int workers) {
  fmt::print("\nPaper scale ({:.0f} frames), rendering only, on {} threads and on a 100-task array:\n\n| mode |", paper,
             workers);
  std::string rule = "|---|";
  for (const ErrorLevel& level : levels)
    fmt::print(" {0}: s per frame | hours | on 100 tasks |", level.label), rule += "---:|---:|---:|";
  fmt::print("\n{}\n", rule);
  for (const SeriesCurves& s : series) {
    fmt::print("| {} |", s.name);
    for (const ErrorLevel& level : levels) {
      const std::optional<Reach> r = mean_reach(s, level);
      fmt::print(" {} | {} | {} |", reach_text(r), reach_text(r, paper / 3600.0),
                 reach_text(r, paper / 3600.0 / 100.0));
    }
    fmt::print("\n");
  }
}

// Frame by frame, the seconds each series needs to reach the level.
void print_frames_at(const std::vector<SeriesCurves>& series, const ErrorLevel& level,
                     const std::vector<std::string>& frame_names) {
  fmt::print("\nFrame by frame, render seconds to the image error {}:\n\n| frame | error, % |", level.label);
  std::string rule = "|---|---:|";
  for (const SeriesCurves& s : series) fmt::print(" {} |", s.name), rule += "---:|";
  fmt::print("\n{}\n", rule);
  for (size_t f = 0; f < frame_names.size(); ++f) {
    fmt::print("| {} | {:.2f} |", frame_names[f], 100.0 * level.errors[f]);
    for (const SeriesCurves& s : series) fmt::print(" {} |", reach_text(reach(s.frames[f], level.errors[f])));
    fmt::print("\n");
  }
}

// What the command line asks for, the same for every setting compared.
struct Request {
  std::string config_file;
  std::vector<std::string> objects, mode_texts;
  std::vector<Series> series;
  std::vector<Mode> modes;  // every series' points, in order
  int views = 1, reference_frames = 4, reference_factor = 8, threads = 0;
  double target_percent = 1.6;
  CyclesOptions cycles;
  std::string images;
  bool object_pixels = false;  // Run::object_pixels
};

// One compared setting's curves (a lighting's, a surroundings'), ours only, and the error its
// frames reach as configured (per frame): what the comparison reads.
struct SettingCurves {
  std::string name;
  std::vector<SeriesCurves> series;
  std::optional<ErrorLevel> as_configured;
};

// Measures every mode on the request's frames under the configuration with `sets`, references
// included, and prints the tables; `name` heads them.
SettingCurves measure_setting(const Request& request, const std::vector<matdataset::Override>& sets,
                                const std::string& name) {
  const std::string& config_file = request.config_file;
  const std::vector<Series>& series = request.series;
  const std::vector<Mode>& modes = request.modes;
  const std::vector<std::string>& mode_texts = request.mode_texts;
  const CyclesOptions& cycles = request.cycles;
  const int reference_factor = request.reference_factor, views = request.views,
            reference_frames = request.reference_frames, threads = request.threads;
  const std::vector<std::string>& objects = request.objects;
  const double target_percent = request.target_percent;
  const std::string& images = request.images;
    std::vector<matdataset::DatasetConfig> configs;
    for (const Mode& mode : modes) {
      std::vector<matdataset::Override> overrides = sets;
      overrides.insert(overrides.end(), mode.overrides.begin(), mode.overrides.end());
      configs.push_back(matdataset::load_config(config_file, overrides));
    }
    const matdataset::DatasetConfig config = matdataset::load_config(config_file, sets);
    const matdataset::DatasetPlan plan = matdataset::plan_dataset(config);
    // The reference: the configuration's fixed samples times reference_factor, and its AO error
    // bound over sqrt(reference_factor).
    std::vector<matdataset::Override> reference_overrides = sets;
    const int reference_samples = config.render.settings.samples_per_pixel * reference_factor;
    reference_overrides.push_back({"render.samples", std::to_string(reference_samples), "--reference-factor"});
    reference_overrides.push_back({"render.ambient_occlusion.error",
                                   fmt::format("{}", config.render.settings.ambient_occlusion_error /
                                                         std::sqrt(static_cast<double>(reference_factor))),
                                   "--reference-factor"});
    const matdataset::DatasetConfig reference = matdataset::load_config(config_file, reference_overrides);
    if (cycles.enabled && !shaders_ref::cycles_available(cycles.blender))
      throw std::runtime_error("--cycles: " + cycles.blender + " --version does not report Blender 3.4");
    const int workers = matbase::worker_threads(threads);
    fmt::print("{}: {} frames of {}x{} at {} spp, AO error bound {}; {} threads; modes:", config_file, plan.frames.size(),
               config.render.width, config.render.height, config.render.settings.samples_per_pixel, config.render.settings.ambient_occlusion_error,
               workers);
    for (const std::string& text : mode_texts) fmt::print(" {}", text);
    if (cycles.enabled)
      fmt::print("; Blender 3.4 Cycles at noise thresholds {} up to {} spp", fmt::join(cycles.thresholds, ", "),
                 cycles.max_samples);
    fmt::print("\n");
    std::fflush(stdout);
    const fs::path scratch = fs::temp_directory_path() / "matpredict_make_dataset_bench";
    fs::remove_all(scratch);
    if (!images.empty()) fs::create_directories(images);

    const Run run{plan, workers, reference_factor, reference_samples, scratch, images, request.object_pixels};
    std::vector<ModeFigures> figures(modes.size()), cycles_figures(cycles.thresholds.size());
    double setup_seconds = 0.0;
    int referenced = 0;
    std::vector<std::string> frame_names;  // of the referenced frames
    for (const std::string& spec : objects) {
      const auto [object, variant] = object_and_variant(spec, config, plan);
      std::vector<Frame> frames;
      for (const size_t view : spread_views(views, plan.views))
        frames.push_back(
            {config.objects[object].name, view, matdataset::frame_seed(config.seed, {object, variant, view}, config.render.settings.seed), {}});
      // The references first, then one renderer at a time: each holds its own scene and materials.
      std::unique_ptr<matdataset::ObjectRenderer> reference_renderer;
      for (size_t k = 0; k < frames.size() && referenced < reference_frames; ++k, ++referenced) {
        if (!reference_renderer) {
          reference_renderer = std::make_unique<matdataset::ObjectRenderer>(reference, object);
          reference_renderer->select_variant(variant, plan.variants[object][variant]);
        }
        frame_names.push_back(fmt::format("{} view {} ({})", frames[k].object, frames[k].view,
                                          reference_renderer->slot_materials().front().material));
        render_reference(run, *reference_renderer, frames[k]);
      }
      for (size_t m = 0; m < modes.size(); ++m) {
        const Clock::time_point setup = Clock::now();
        matdataset::ObjectRenderer renderer(configs[m], object);
        renderer.select_variant(variant, plan.variants[object][variant]);
        setup_seconds += seconds_since(setup) / static_cast<double>(modes.size());
        if (m == 0)
          fmt::print("{} variant {} ({}): set up in {:.1f} s\n", frames.front().object, variant,
                     renderer.slot_materials().front().material, seconds_since(setup));
        measure_mode(run, renderer, modes[m].name, frames, figures[m]);
      }
      // The reference's scene is the frames' (only samples and the AO bound differ).
      if (cycles.enabled && reference_renderer)
        measure_cycles(run, cycles, *reference_renderer, config.render, frames, cycles_figures);
    }
    const double paper = static_cast<double>(plan.frames.size());
    fmt::print("\nobject set-up (scene, BVH, one {}-texel material): {:.1f} s per object and variant\n\n",
               config.render.material_resolution, setup_seconds / objects.size());
    print_points(modes, figures, scratch, cycles.thresholds, cycles_figures, paper, workers);
    fs::remove_all(scratch);
    if (referenced == 0) return {name, {}, std::nullopt};

    std::vector<SeriesCurves> curves;
    for (size_t s = 0, first = 0; s < series.size(); first += series[s].points.size(), ++s) {
      std::vector<const ModeFigures*> points;
      for (size_t p = first; p < first + series[s].points.size(); ++p) points.push_back(&figures[p]);
      curves.push_back(series_curves(series[s].name, points));
    }
    std::optional<SeriesCurves> cycles_curves;
    if (cycles.enabled) {
      std::vector<const ModeFigures*> points;
      for (const ModeFigures& f : cycles_figures) points.push_back(&f);
      cycles_curves = series_curves("Cycles 3.4", points);
    }
    // The levels: the target on every frame; what the point rendering as the configuration does
    // reaches on each frame; what each of Cycles' does.
    std::vector<ErrorLevel> levels = {{fmt::format("{:.2f} % on every frame", target_percent),
                                       std::vector<double>(static_cast<size_t>(referenced), target_percent / 100.0)}};
    const auto as_configured = [&](const matdataset::DatasetConfig& c) {
      return same_sampling(c.render, config.render);
    };
    const size_t configured =
        static_cast<size_t>(std::find_if(configs.begin(), configs.end(), as_configured) - configs.begin());
    SettingCurves result{name, curves, std::nullopt};
    if (configured < modes.size()) {
      result.as_configured = ErrorLevel{fmt::format("as {}, mean {:.2f} %", modes[configured].name,
                                                    100.0 * average(figures[configured].image_errors)),
                                        figures[configured].image_errors};
      levels.push_back(*result.as_configured);
    }
    const size_t projected = levels.size();
    for (size_t t = 0; cycles_curves && t < cycles.thresholds.size(); ++t)
      levels.push_back({fmt::format("as Cycles 3.4 threshold {}, mean {:.2f} %", cycles.thresholds[t],
                                    100.0 * average(cycles_figures[t].image_errors)),
                        cycles_figures[t].image_errors});
    print_equal_error(curves, cycles_curves, levels);
    if (cycles_curves) curves.push_back(*cycles_curves);
    print_projection(curves, {levels.begin(), levels.begin() + static_cast<std::ptrdiff_t>(projected)}, paper, workers);
    for (size_t l = 0; l < projected; ++l) print_frames_at(curves, levels[l], frame_names);
    return result;
}

// Under each compared setting (`what`: "lighting", "surroundings"), the render seconds a frame each
// series needs to reach the error the first setting's frames have as configured (the rig's at 128
// samples for paper.yaml), and their ratio to the first one's: what a setting costs at equal error.
void print_setting_costs(const std::vector<SettingCurves>& lightings, const std::string& what) {
  const SettingCurves& first = lightings.front();
  if (!first.as_configured) return;
  const ErrorLevel& level = *first.as_configured;
  fmt::print("\nRender seconds a frame under each {} to the image error {} reaches {} (mean over the "
             "frames, each at its own error under {}), and over {}'s:\n\n| {} |",
             what, first.name, level.label, first.name, first.name, what);
  std::string rule = "|---|";
  for (const SeriesCurves& s : first.series) fmt::print(" {0} | {0} / {1} |", s.name, first.name), rule += "---:|---:|";
  fmt::print("\n{}\n", rule);
  for (const SettingCurves& lighting : lightings) {
    fmt::print("| {} |", lighting.name);
    for (size_t k = 0; k < first.series.size(); ++k) {
      const std::optional<Reach> base = mean_reach(first.series[k], level);
      const std::optional<Reach> here =
          k < lighting.series.size() ? mean_reach(lighting.series[k], level) : std::optional<Reach>();
      fmt::print(" {} | {} |", reach_text(here), ratio_text(here, base));
    }
    fmt::print("\n");
  }
}


}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "make_dataset_bench: frames per hour at the paper's settings, their error against a high-sample "
      "reference, and the time and disk this projects for the paper-scale dataset, for each way of "
      "rendering side by side (and Blender 3.4 Cycles with --cycles), as time to equal error"};
  std::string config_file = MATPREDICT_PAPER_CONFIG;
  // Wood, fabric (velvet), metal and glass (configs/paper.yaml's variants 6, 1, 3 and 13).
  std::vector<std::string> objects = {"chair:6", "vase:3", "sofa:1", "bottle:13"};
  // The adaptive series may take up to 4x the configuration's 128 samples, as Cycles does (CyclesOptions).
  std::vector<std::string> mode_texts = {
      "fixed:render.samples=32|64|128", "adaptive:render.noise_threshold=0.05|0.02|0.01|0.005,render.samples=512",
      "adaptive+denoise:render.noise_threshold=0.05|0.02|0.01|0.005,render.samples=512,render.denoise=filter"};
  std::vector<std::string> set_texts, lighting_texts, surroundings_texts;
  int views = 1, reference_frames = 4, reference_factor = 8, threads = 0;
  double target_percent = 1.6;
  CyclesOptions cycles;
  std::string images;
  app.add_option("--config", config_file, "the configuration whose settings are measured")->capture_default_str();
  app.add_option("--set", set_texts, "KEY=VALUE: set a key of the configuration for every mode and the reference");
  app.add_option("--objects", objects, "objects of the configuration to render, NAME or NAME:VARIANT (default: the "
                                       "object's index modulo its variants)")
      ->capture_default_str();
  app.add_option("--mode", mode_texts,
                 "NAME or NAME:KEY=VALUE,...: a way of rendering, compared on the same frames; one VALUE may be "
                 "v1|v2|..., a series of one point per value, listed by increasing cost")
      ->capture_default_str();
  app.add_option("--views", views, "views per object, spread over the grid")->capture_default_str()->check(CLI::Range(1, 64));
  app.add_option("--reference-frames", reference_frames, "frames also rendered as a reference (the first ones)")
      ->capture_default_str()
      ->check(CLI::Range(0, 64));
  app.add_option("--reference-factor", reference_factor, "the reference's samples and AO trials over the frame's")
      ->capture_default_str()
      ->check(CLI::Range(2, 256));
  app.add_option("--target-error", target_percent,
                 "image RMSE, % of the object's mean, on every frame: where the times to equal error and the "
                 "paper-scale projection are read, beside the error the configuration's own sampling has on each")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--lighting", lighting_texts,
                 "NAME=YAML: a `lights` value (docs/make_dataset.md, \"Lighting\"); every mode is measured under each "
                 "in turn, references included, and a last table gives each lighting's render seconds to the error "
                 "the first one's frames have as configured, over the first one's");
  app.add_option("--surroundings", surroundings_texts,
                 "NAME=YAML: a `surroundings` value (docs/make_dataset.md, \"Surroundings\"), compared as --lighting "
                 "compares lightings: what a floor, a room or distractors cost at equal error, the image error "
                 "taken on the object's pixels (its reference's label) alone")
      ->excludes(app.get_option("--lighting"));
  app.add_flag("--cycles", cycles.enabled, "also render the referenced frames with Blender 3.4 Cycles");
  app.add_option("--blender", cycles.blender, "Blender 3.4 executable")->capture_default_str();
  app.add_option("--cycles-thresholds", cycles.thresholds, "Cycles' noise thresholds, a render each, the loosest first")
      ->capture_default_str()
      ->check(CLI::Range(1e-6, 1.0));
  app.add_option("--cycles-max-samples", cycles.max_samples, "Cycles' Max Samples under adaptive sampling")
      ->capture_default_str()
      ->check(CLI::Range(1, 1 << 16));
  app.add_option("--images", images, "folder for the converged references as PNGs (ours, and Cycles' with --cycles)");
  app.add_option("--threads", threads, "render threads, 0 every hardware thread")->capture_default_str()->check(CLI::NonNegativeNumber);
  CLI11_PARSE(app, argc, argv);
  try {
    std::vector<matdataset::Override> sets;
    for (const std::string& text : set_texts) sets.push_back(parse_override(text, "--set"));
    std::vector<Series> series;
    for (const std::string& text : mode_texts) series.push_back(parse_series(text));
    std::vector<Mode> modes;
    for (const Series& s : series) modes.insert(modes.end(), s.points.begin(), s.points.end());
    Request request{config_file, objects, mode_texts, series, modes, views, reference_frames, reference_factor,
                    threads, target_percent, cycles, images, !surroundings_texts.empty()};
    // Each setting compared in turn under one configuration key.
    const bool lights = !lighting_texts.empty();
    const std::vector<std::string>& compared = lights ? lighting_texts : surroundings_texts;
    if (compared.empty()) {
      measure_setting(request, sets, "the configuration's lighting");
      return 0;
    }
    const std::string option = lights ? "--lighting" : "--surroundings", key = lights ? "lights" : "surroundings",
                      what = lights ? "lighting" : "surroundings";
    std::vector<SettingCurves> curves;
    for (const std::string& text : compared) {
      const matdataset::Override setting = parse_override(text, option);
      std::vector<matdataset::Override> with = sets;
      with.push_back({key, setting.value, option + " " + setting.key});
      fmt::print("\n## {} {}: {}\n\n", lights ? "Lighting" : "Surroundings", setting.key, setting.value);
      curves.push_back(measure_setting(request, with, setting.key));
    }
    print_setting_costs(curves, what);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "make_dataset_bench: %s\n", e.what());
    return 1;
  }
}
