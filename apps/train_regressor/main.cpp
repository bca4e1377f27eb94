// train_regressor: trains a network that predicts material maps (and optionally material
// classes) from one RGB image, on a dataset in the MatPredict repository's layout.
#include <cstdio>
#include <fstream>
#include <iostream>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "common/command_line.h"
#include "common/exit_codes.h"
#include "common/interrupt.h"
#include "common/number_options.h"
#include "common/progress_bar.h"
#include "common/thread_count.h"
#include "example_dataset.h"
#include "matbase/file/atomic_file.h"
#include "matdataset/format/dataset_error.h"
#include "matlearn/models/regressor.h"
#include "matlearn/training/trainer.h"
#include "training_options.h"

namespace {

using namespace train_regressor;

// The paper's table (millions of parameters) for its four networks.
double paper_millions(matlearn::Architecture a) {
  switch (a) {
    case matlearn::Architecture::unet_no_skip: return 23.6;
    case matlearn::Architecture::resnet50_u: return 39.5;
    case matlearn::Architecture::swin_t_u: return 31.6;
    case matlearn::Architecture::convnext_t_u: return 32.0;
    default: return 0.0;
  }
}

void describe(const matlearn::TrainingConfig& config) {
  const int64_t outputs = config.layout.output_channels();
  fmt::print("Networks for {} output channels ({} map channels, {} material classes):\n", outputs,
             config.layout.regression_channels(), config.layout.material_classes);
  fmt::print("  {:<20} {:>12} {:>15}  {}\n", "network", "parameters", "paper", "design");
  for (const matlearn::ArchitectureInfo& a : matlearn::architectures()) {
    const int64_t count = matlearn::parameter_count(*matlearn::make_regressor(a.architecture, outputs));
    const double paper = paper_millions(a.architecture);
    const std::string paper_text =
        paper > 0 ? fmt::format("{:.1f}M ({:+.2f}%)", paper, 100.0 * (static_cast<double>(count) / (paper * 1e6) - 1.0))
                  : "-";
    fmt::print("  {:<20} {:>12} {:>15}  {}\n", a.name, matbase::with_thousands(count), paper_text, a.description);
  }
  if (config.width_divisor != 1) {
    const auto thin = matlearn::make_regressor(matlearn::architecture_named(config.network).architecture, outputs,
                                               config.width_divisor);
    fmt::print("  {} with widths / {}: {} parameters\n", config.network, config.width_divisor,
               matbase::with_thousands(matlearn::parameter_count(*thin)));
  }
  fmt::print("The paper's counts are for 6 outputs (base colour 3 + roughness 3).\n");
}

// With no arguments: a tiny dataset rendered here, and a small network trained on it for a few
// minutes.
void use_example(Options& options) {
  const std::filesystem::path root = std::filesystem::path("train_output") / "example_dataset";
  fmt::print("no dataset given: rendering the example dataset (2 built-in objects x 4 materials x 8 views, 64 px) "
             "into {}\n",
             root.string());
  std::fflush(stdout);
  app_support::ProgressBar bar("render");
  render_example_dataset(root, ExampleDatasetSize{}, [&bar](int done, int total) {
    bar.update(static_cast<double>(done) / static_cast<double>(total));
  });
  bar.finish();
  options.command_line = {{"dataset_root", root.string()}, {"width_divisor", "4"}, {"image_size", "64"},
                          {"epochs", "40"},                {"batch_size", "8"},    {"lr", "1e-3"},
                          {"output_dir", "train_output"}};
}

int train(Options options, bool example) {
  if (example) use_example(options);
  const std::map<std::string, std::string> settings = resolve_settings(options);
  const matlearn::TrainingConfig config = training_config(settings, !options.describe);
  if (options.describe) {
    describe(config);
    return 0;
  }
  matlearn::Trainer trainer(config);
  // Says so when the request is more than the machine has; the trainer caps it the same way.
  app_support::announced_worker_threads("train_regressor", "--threads", config.threads);
  const std::filesystem::path last = config.output_dir / "checkpoints" / "last.pt";
  const std::string pretrained = settings.at("pretrained_model");
  if (options.resume || !pretrained.empty()) {
    // --resume continues this folder's own run, also when its config.yaml names the checkpoint
    // the run started from.
    const std::filesystem::path from = options.resume ? last : std::filesystem::path(pretrained);
    try {
      trainer.resume(from);
    } catch (const std::exception& e) {
      throw matbase::InputError(e.what());
    }
    if (trainer.epochs_done() > config.epochs)
      throw matbase::InputError(fmt::format("{} already holds epoch {}, beyond the {} epochs asked for; nothing was trained "
                                   "(ask for more epochs, or give another --output-dir for a new run)",
                                   from.string(), trainer.epochs_done(), config.epochs));
    if (trainer.epochs_done() == config.epochs) {
      fmt::print("{} already holds all {} epochs; nothing to train\n", from.string(), config.epochs);
      return 0;
    }
    fmt::print("resuming after epoch {} from {}\n", trainer.epochs_done(), from.string());
  }
  std::filesystem::create_directories(config.output_dir);
  matbase::write_file_atomically(config.output_dir / "config.yaml", settings_yaml(settings));
  fmt::print("training {} ({} parameters) on {} samples, validating on {}; {} epochs of batch {} at {} px\n",
             config.network, matlearn::parameter_count(trainer.model()), config.train_samples.size(),
             config.validation_samples.size(), config.epochs, config.batch_size, config.image_size);
  std::fflush(stdout);

  std::unique_ptr<app_support::ProgressBar> bar;
  matlearn::TrainingCallbacks callbacks;
  callbacks.cancel = app_support::cancel_on_interrupt();
  callbacks.step = [&](int epoch, size_t step, size_t steps, double loss) {
    if (step == 1) bar = std::make_unique<app_support::ProgressBar>(fmt::format("epoch {}/{}", epoch, config.epochs));
    bar->update(static_cast<double>(step) / static_cast<double>(steps), fmt::format("loss {:.5f}", loss));
  };
  callbacks.epoch_finished = [&](const matlearn::EpochReport& r) {
    if (bar) bar->finish();
    const std::string validation = r.validated ? fmt::format("  validation {:.5f}", r.validation_loss) : "";
    fmt::print("epoch {}/{}: train {:.5f}{}  rate {:.3g}  {:.1f} s\n", r.epoch, config.epochs, r.train_loss,
               validation, r.learning_rate, r.seconds);
    std::fflush(stdout);
  };
  bool finished = false;
  try {
    finished = trainer.train(callbacks);
  } catch (const matlearn::TrainingDiverged& e) {
    if (bar) bar->finish();
    // The trainer writes no checkpoint of a diverged epoch, so last.pt is the last good one.
    throw std::runtime_error(std::string(e.what()) + "; " +
                             (trainer.epochs_done() > 0 && std::filesystem::exists(last)
                                  ? fmt::format("{} still holds epoch {}, the last that finished", last.string(),
                                                trainer.epochs_done())
                                  : std::string("no checkpoint was written")));
  } catch (...) {
    if (bar) bar->finish();  // the error's line below the bar's, not on it
    throw;
  }
  if (!finished) {
    if (bar) bar->finish();
    // config.yaml holds every setting of this run, so the command below is the whole of it.
    const std::string resume_command =
        fmt::format("train_regressor --config {} --resume", (config.output_dir / "config.yaml").string());
    if (std::filesystem::exists(last))
      fmt::print(stderr, "train_regressor: interrupted; {} holds epoch {}; continue with: {}\n", last.string(),
                 trainer.epochs_done(), resume_command);
    else
      fmt::print(stderr, "train_regressor: interrupted before the first epoch finished; no checkpoint was written, "
                 "so run the same command again to start over\n");
    return app_support::interrupted_exit_code();
  }
  fmt::print("wrote {}: checkpoints/last.pt{}, log.csv (one row per epoch), config.yaml (the settings)\n",
             config.output_dir.string(),
             std::filesystem::exists(config.output_dir / "checkpoints" / "best.pt") ? ", checkpoints/best.pt" : "");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Trains a network that predicts material maps (base colour, roughness, metallic) and optionally material "
      "classes from one RGB image, on a dataset in the MatPredict repository's layout. Settings come from the "
      "defaults (the paper's protocol), then --config, then the options below.",
      "train_regressor"};
  Options options;
  add_options(app, options);
  if (const std::optional<int> exit_code = app_support::parse_command_line(app, argc, argv, "train_regressor"))
    return *exit_code;
  try {
    return train(options, /*example=*/argc == 1);
  } catch (const matbase::InputError& e) {
    return app_support::report_error("train_regressor", e.what(), app_support::kInputError);
  } catch (const matdataset::DatasetError& e) {
    return app_support::report_error("train_regressor", e.what(), app_support::kInputError);
  } catch (const std::exception& e) {
    return app_support::report_error("train_regressor", e.what(), app_support::kRuntimeFailure);
  }
}
