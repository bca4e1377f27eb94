// make_dataset: renders a MatPredict dataset (every object in every material variant from every
// view of the camera grid, with pixel-aligned maps) into the repository's layout, resumably and
// in shards. This file only parses the command line, calls the parts that do the work and reports.
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "common/command_line.h"
#include "common/exit_codes.h"
#include "common/interrupt.h"
#include "common/number_options.h"
#include "common/progress_bar.h"
#include "common/thread_count.h"
#include "matbase/memory_limit.h"
#include "matdataset/format/dataset_writer.h"
#include "matdataset/format/verify_dataset.h"
#include "matdataset/maker/dataset_config.h"
#include "matdataset/maker/dataset_plan.h"
#include "matdataset/maker/dataset_preview.h"
#include "matdataset/maker/dataset_run.h"

using matbase::InputError;
using matdataset::Override;

namespace {

using app_support::kInputError;
using app_support::kRuntimeFailure;

int report_error(const std::string& message, int exit_code) {
  return app_support::report_error("make_dataset", message, exit_code);
}

struct Options {
  std::string config_file;
  std::vector<std::string> sets;  // KEY=VALUE
  std::vector<Override> named;    // from the named options
  std::string shard = "0/1";
  int threads = 0;
  bool print_config = false;
  bool list_render_keys = false;
  std::string verify;   // a dataset folder to check instead of rendering
  std::string preview;  // a dataset folder to draw contact sheets of
};

// A YAML double-quoted string: any text stays one scalar.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) out += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
  return out + "\"";
}

std::vector<std::string> comma_list(const std::string& text) {
  std::vector<std::string> items;
  for (size_t start = 0;;) {
    const size_t comma = text.find(',', start);
    items.push_back(text.substr(start, comma - start));
    if (comma == std::string::npos) return items;
    start = comma + 1;
  }
}

// "AxB" as the YAML list "[A, B]", unchecked: the configuration's reader names what is wrong.
std::string pair_list(const std::string& text, const std::string& option) {
  const size_t x = text.find('x');
  if (x == std::string::npos) throw matbase::InputError(option + ": expected AxB, got " + text);
  return "[" + quoted(text.substr(0, x)) + ", " + quoted(text.substr(x + 1)) + "]";
}

void add_options(CLI::App& app, Options& options) {
  app.add_option("-c,--config", options.config_file,
                 "YAML or JSON configuration (docs/make_dataset.md); none: the embedded default (--print-config shows it)");
  app.add_option("--set", options.sets, "KEY=VALUE: set any key of the configuration, dotted (render.samples=128)")
      ->type_name("KEY=VALUE");
  auto named = [&](const std::string& flags, const std::string& key, const std::string& help,
                   std::function<std::string(const std::string&, const std::string&)> to_yaml) {
    const std::string option = flags.substr(flags.rfind(',') + 1);
    app.add_option_function<std::string>(
           flags,
           [&options, key, option, to_yaml](const std::string& value) {
             options.named.push_back({key, to_yaml(value, option), option, true});
           },
           help + " (" + key + ")")
        ->type_name("VALUE");
  };
  const auto scalar = [](const std::string& value, const std::string&) { return quoted(value); };
  const auto pair = [](const std::string& value, const std::string& option) { return pair_list(value, option); };
  named("-o,--output", "output", "the dataset's folder", scalar);
  named("--objects", "objects", "built-in objects NAME[:SEED], comma-separated, replacing the configuration's",
        [](const std::string& value, const std::string&) {
          std::string yaml = "[";
          for (const std::string& item : comma_list(value)) {
            const size_t colon = item.find(':');
            yaml += (yaml.size() > 1 ? ", " : "") + std::string("{builtin: ") + quoted(item.substr(0, colon)) +
                    (colon == std::string::npos ? "" : ", seed: " + quoted(item.substr(colon + 1))) + "}";
          }
          return yaml + "]";
        });
  named("--materials", "materials", "candidate materials CLASS[/STYLE][:SEED], comma-separated, one slot for every part of "
        "objects without materials of their own",
        [](const std::string& value, const std::string&) {
          std::string yaml = "{all: [";
          for (const std::string& item : comma_list(value)) yaml += (yaml.size() > 7 ? ", " : "") + quoted(item);
          return yaml + "]}";
        });
  named("--strategy", "variants.strategy", "cartesian or zip", scalar);
  named("--max-variants", "variants.max_variants", "at most this many variants per object, drawn uniformly", scalar);
  named("--resolution", "render.resolution", "WxH pixels",
        [](const std::string& value, const std::string& option) {
          return value.find('x') == std::string::npos ? quoted(value) : pair_list(value, option);
        });
  named("--spp", "render.samples", "samples per pixel (with --noise-threshold: the most a pixel takes)", scalar);
  named("--noise-threshold", "render.noise_threshold", "adaptive sampling as Cycles' Noise Threshold (0: off)", scalar);
  named("--denoise", "render.denoise", "false, filter or learned: denoise each image (docs/conventions.md, \"Denoising\")",
        scalar);
  named("--exposure", "render.exposure", "stops applied to the images, or auto (the grey-card rule)", scalar);
  named("--ao-error", "render.ambient_occlusion.error", "the standard error ORM's R may have at most", scalar);
  named("--material-resolution", "render.material_resolution", "texels per side of library materials", scalar);
  named("--grid", "camera.grid", "N_PHIxN_THETA cameras", pair);
  named("--illuminance", "lights.illuminance_lux", "lux at the object's centre", scalar);
  named("--seed", "seed", "of every frame's samples", scalar);
  app.add_option("--shard", options.shard, "render shard K of N (0 <= K < N): frames k with k mod N = K")
      ->type_name("K/N");
  app.add_option("-t,--threads", options.threads, "render threads (0: all); the images do not depend on it")
      ->check(app_support::whole_number_in(0, app_support::kMaxThreadRequest));
  app.add_option("--verify", options.verify,
                 "check the dataset in DIR (every map of every frame, sizes, labels, masks, records, splits) and exit: "
                 "1 when a problem is found")
      ->type_name("DIR");
  app.add_option("--preview", options.preview,
                 "draw a contact sheet per object and variant of the dataset in DIR (views x maps) and an "
                 "index.html linking them, into DIR/preview/, and exit")
      ->type_name("DIR");
  app.add_flag("--print-config", options.print_config, "print the configuration after overrides, and exit");
  app.add_flag("--list-render-keys", options.list_render_keys,
               "print the render settings the configuration's `render:` block takes (a markdown table), and exit");
}

std::vector<Override> overrides(const Options& options) {
  std::vector<Override> all = options.named;
  for (const std::string& set : options.sets) {
    const size_t equals = set.find('=');
    if (equals == std::string::npos || equals == 0) throw matbase::InputError("--set: expected KEY=VALUE, got " + set);
    all.push_back({set.substr(0, equals), set.substr(equals + 1), "--set " + set.substr(0, equals)});
  }
  return all;
}

int verify(const std::string& folder) {
  const matdataset::VerifyReport report = matdataset::verify_dataset(folder);
  constexpr size_t kShown = 50;
  for (size_t k = 0; k < std::min(report.problems.size(), kShown); ++k) fmt::print("{}\n", report.problems[k]);
  if (report.problems.size() > kShown) fmt::print("... and {} more\n", report.problems.size() - kShown);
  fmt::print("verified {}: {} variants, {} frames: {}\n", folder, report.variants, report.frames,
             report.problems.empty() ? "no problem" : fmt::format("{} problems", report.problems.size()));
  return report.problems.empty() ? 0 : kRuntimeFailure;
}

int preview(const std::string& folder) {
  const matdataset::PreviewSummary summary = matdataset::write_preview(folder);
  fmt::print("wrote {} contact sheets and {}: open it in a browser\n", summary.sheets, summary.index.string());
  if (summary.damaged.empty()) return 0;
  for (const std::string& problem : summary.damaged) fmt::print("{}\n", problem);
  return report_error(fmt::format("{} maps could not be read; the sheets draw them as red and black stripes, and "
                                  "--verify checks the whole dataset",
                                  summary.damaged.size()),
                      kRuntimeFailure);
}

int make(const Options& options) {
  if (options.list_render_keys) {
    fmt::print("{}", matdataset::dataset_render_keys_markdown());
    return 0;
  }
  const std::optional<matdataset::Shard> shard = matdataset::parse_shard(options.shard);
  if (!shard) throw matbase::InputError("--shard: expected K/N with 0 <= K < N, got " + options.shard);
  const matdataset::DatasetConfig config = matdataset::load_config(options.config_file, overrides(options));
  if (options.print_config) {
    fmt::print("# output: {}\n{}", config.output, config.canonical_yaml);
    return 0;
  }
  const matdataset::DatasetPlan plan = matdataset::plan_dataset(config);
  size_t variants = 0;
  for (const auto& object : plan.variants) variants += object.size();
  fmt::print("make_dataset: {} objects, {} variants, {} views each: {} frames of {}x{} at {} spp{} into {}\n",
             config.objects.size(), variants, plan.views, matbase::with_thousands(static_cast<int64_t>(plan.frames.size())),
             config.render.width, config.render.height, config.render.settings.samples_per_pixel,
             shard->count > 1 ? fmt::format(" (shard {}/{})", shard->index, shard->count) : "", config.output);
  for (size_t o = 0; o < config.objects.size(); ++o)
    if (const size_t under = plan.grid_views_under_floor[o].size(); under > 0)
      fmt::print("make_dataset: {}: {} of the grid's {} cameras are under its floor and left out ({} frames fewer)\n",
                 config.objects[o].name, under, plan.grid_views,
                 (plan.views - plan.object_views[o].size()) * plan.variants[o].size());
  std::fflush(stdout);

  matdataset::RunOptions run;
  run.shard = *shard;
  run.threads = app_support::announced_worker_threads("make_dataset", "--threads", options.threads);
  run.cancel = app_support::cancel_on_interrupt();
  run.note = [](const std::string& note) { fmt::print(stderr, "make_dataset: note: {}\n", note); };
  app_support::ProgressBar bar("frames");
  const auto start = std::chrono::steady_clock::now();
  run.progress = [&](size_t done, size_t total, size_t rendered) {
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    bar.update(static_cast<double>(done) / static_cast<double>(std::max<size_t>(total, 1)),
               fmt::format("{}/{} frames, {:.2f} frames/s", done, total, rendered / std::max(seconds, 1e-9)));
  };
  const matdataset::RunSummary summary = matdataset::run_dataset(config, plan, run);
  bar.finish();
  const double rate = summary.rendered / std::max(summary.render_seconds, 1e-9);
  fmt::print("rendered {} frames and found {} complete, of {} in this shard, in {:.1f} s ({:.2f} frames/s, "
             "{:.0f} frames/hour)\n",
             summary.rendered, summary.skipped, summary.frames, summary.seconds, rate, rate * 3600.0);
  if (summary.cancelled)
    return report_error(fmt::format("interrupted: {} of {} frames are done; run the same command again to resume",
                                    summary.rendered + summary.skipped, summary.frames),
                        app_support::interrupted_exit_code());
  for (const matdataset::SplitFile& split : summary.splits)
    fmt::print("split {}: {} train, {} val, {} test{}\n", split.name, split.train.size(), split.val.size(),
               split.test.size(),
               split.train.empty() || split.test.empty() || (split.val.empty() && split.strategy != "random")
                   ? (split.strategy == "lighting_disjoint" ? " (too few lightings to fill every split)"
                                                            : " (too few groups to fill every split)")
                   : "");
  std::string folders;
  for (const matdataset::DatasetMapInfo& map : matdataset::dataset_maps()) {
    bool written = false;
    for (size_t object = 0; object < config.objects.size(); ++object)
      written |= matdataset::frame_has_map(map, matdataset::frame_contents(config, object));
    if (written) folders += std::string(map.folder) + "/, ";
  }
  fmt::print("wrote {} ({}): per object and variant {}transforms.json, metadata.json; config/ holds the split files\n",
             config.output, matbase::byte_size_text(static_cast<double>(matdataset::folder_bytes(config.output))),
             folders);
  if (summary.redrawn_frames > 0)
    fmt::print("{} frames drew their distractors again because the first draw hid too much of the object\n",
               summary.redrawn_frames);
  if (!summary.hidden_frames.empty())
    fmt::print(stderr,
               "make_dataset: {} frames show less of the object than their surroundings' visible_fraction (the "
               "first: {}); distractors are kept at their best draw, and fewer or smaller ones, or more tries, would "
               "show more; in a scan, other camera angles (camera.phi_deg, camera.radius) would\n",
               summary.hidden_frames.size(), summary.hidden_frames.front());
  // Written, as rendered, but a frame without the object trains to a loss of 0: not a success.
  if (!summary.empty_frames.empty())
    return report_error(fmt::format("{} frames show the object in no pixel (the first: {}); are the cameras too far "
                                    "(camera.radius) or the resolution too low?",
                                    summary.empty_frames.size(), summary.empty_frames.front()),
                        kRuntimeFailure);
  // A black frame teaches nothing about the material either.
  if (!summary.unlit_frames.empty())
    return report_error(fmt::format("{} frames are black: none of their light reaches the object through its surroundings "
                                    "(the first: {}); a closed room or scan lets no environment or sky in, and lamps "
                                    "outside its walls light only the walls: light it from inside (a ceiling lamp, the rig)",
                                    summary.unlit_frames.size(), summary.unlit_frames.front()),
                        kRuntimeFailure);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Renders a MatPredict dataset: every object in every material variant from every view of the "
               "paper's camera grid, with pixel-aligned albedo, ORM, depth, normals and labels, in the MatPredict "
               "repository's layout. With no arguments it renders a small embedded default (6 objects x 3 "
               "materials x 8 views, 128 px) into ./dataset_out/. A run that is stopped resumes when started again.",
               "make_dataset"};
  app.footer("Exit codes: 0 done, 1 render or write failure, 2 bad option or input, 130 or 143 interrupted by "
             "Ctrl-C or SIGTERM (finished frames are kept; run again to resume).");
  Options options;
  add_options(app, options);
  try {
    if (const std::optional<int> exit_code = app_support::parse_command_line(app, argc, argv, "make_dataset"))
      return *exit_code;
  } catch (const matbase::InputError& e) {  // a value an option refuses as it reads it (--grid 4)
    return report_error(e.what(), kInputError);
  }
  try {
    if (!options.verify.empty()) return verify(options.verify);
    if (!options.preview.empty()) return preview(options.preview);
    return make(options);
  } catch (const matbase::InputError& e) {
    return report_error(e.what(), kInputError);
  } catch (const std::filesystem::filesystem_error& e) {
    return report_error(app_support::filesystem_error_text(e), kRuntimeFailure);
  } catch (const std::exception& e) {
    return report_error(e.what(), kRuntimeFailure);
  }
}
