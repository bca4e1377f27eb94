// train_denoiser: trains the learned denoiser (matlearn/denoising) on pairs make_dataset rendered:
// the same frames at few samples and at many. scripts/train_denoiser.sh renders the pairs the
// committed weights were trained on and runs it; docs/denoising.md says how.
#include <cstdio>
#include <filesystem>
#include <memory>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "common/command_line.h"
#include "common/exit_codes.h"
#include "common/interrupt.h"
#include "common/number_options.h"
#include "common/progress_bar.h"
#include "common/thread_count.h"
#include "matbase/input_error.h"
#include "matdataset/format/dataset_error.h"
#include "matdataset/maker/example_pairs.h"
#include "matlearn/denoising/denoiser_training.h"

namespace {

namespace fs = std::filesystem;

// With no arguments: small example pairs rendered here (matdataset/maker/example_pairs.h: 64 px,
// 4 samples against 256), and a short run on them.
void use_example(matlearn::DenoiserTrainingSettings& settings) {
  const fs::path root = "train_denoiser_out";
  fmt::print("no pairs given: rendering example pairs (2 built-in objects x 2 materials x 2 views, 64 px, 4 against "
             "256 samples) into {}\n",
             root.string());
  std::fflush(stdout);
  std::unique_ptr<app_support::ProgressBar> bar;
  std::string current;
  const matdataset::ExamplePairs pairs =
      matdataset::render_example_pairs(root, 64, 256, 4, [&](const char* dataset, size_t done, size_t total) {
        if (current != dataset) {
          if (bar) bar->finish();
          bar = std::make_unique<app_support::ProgressBar>(dataset);
          current = dataset;
        }
        bar->update(static_cast<double>(done) / static_cast<double>(total));
      });
  if (bar) bar->finish();
  settings.reference = pairs.reference;
  settings.noisy = {pairs.noisy};
  settings.weights = root / "denoiser.pt";
  settings.steps = 20;
  settings.batch = 4;
  settings.crop = 64;
  settings.checkpoint_every = 10;
}

void require_dataset_folder(const fs::path& folder, const char* option) {
  std::error_code error;
  if (!fs::is_directory(folder, error))
    throw matbase::InputError(fmt::format("{} {}: no such folder (a dataset make_dataset wrote)", option, folder.string()));
}

int train(matlearn::DenoiserTrainingSettings settings, bool example) {
  if (example) use_example(settings);
  for (const fs::path& dataset : settings.noisy) require_dataset_folder(dataset, "--noisy");
  require_dataset_folder(settings.reference, "--reference");
  settings.threads = app_support::announced_worker_threads("train_denoiser", "--threads", settings.threads);
  const fs::path checkpoint = matlearn::denoiser_checkpoint_path(settings.weights);
  fmt::print("training the learned denoiser on {} noisy dataset(s) against {}: {} steps of {} crops of {} px{}\n",
             settings.noisy.size(), settings.reference.string(), settings.steps, settings.batch, settings.crop,
             fs::exists(checkpoint) ? ", continuing from " + checkpoint.string() : std::string());
  std::fflush(stdout);
  if (!settings.weights.parent_path().empty()) fs::create_directories(settings.weights.parent_path());
  app_support::ProgressBar bar("steps");
  bool finished = false;
  try {
    finished = matlearn::train_denoiser(
        settings,
        [&bar](const matlearn::DenoiserTrainingProgress& p) {
          bar.update(static_cast<double>(p.step) / static_cast<double>(p.steps), fmt::format("loss {:.5f}", p.loss));
        },
        app_support::cancel_on_interrupt());
  } catch (...) {
    bar.finish();
    throw;
  }
  bar.finish();
  if (!finished) {
    fmt::print(stderr, "train_denoiser: interrupted; {} holds the last checkpoint; the same command continues from it\n",
               checkpoint.string());
    return app_support::interrupted_exit_code();
  }
  fmt::print("wrote {} (the weights) and {} (the run's state, for more steps)\n", settings.weights.string(),
             checkpoint.string());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Trains the learned denoiser (render.denoise: learned) on pairs make_dataset rendered with "
               "render.hdr_images: the same frames at few samples (--noisy, one dataset per sample count) and at many "
               "(--reference). Continues from the checkpoint beside the weights when there is one. With no arguments "
               "it renders small example pairs and trains on them for 20 steps.",
               "train_denoiser"};
  matlearn::DenoiserTrainingSettings settings;
  settings.weights = "denoiser.pt";
  app.add_option("--reference", settings.reference, "the dataset at many samples")->type_name("DIR");
  app.add_option("--noisy", settings.noisy, "the datasets of the same frames at few samples")->type_name("DIR...");
  app.add_option("--output", settings.weights, "the weights file; its checkpoint is WEIGHTS.checkpoint")
      ->type_name("WEIGHTS")
      ->capture_default_str();
  app.add_option("--steps", settings.steps, "training steps")
      ->check(app_support::whole_number_in(1, 10000000))
      ->capture_default_str();
  app.add_option("--batch", settings.batch, "crops per step")->check(app_support::whole_number_in(1, 1024))->capture_default_str();
  app.add_option("--crop", settings.crop, "crop side in pixels, a multiple of 16")
      ->check(app_support::whole_number_in(16, 4096))
      ->capture_default_str();
  app.add_option("--learning-rate", settings.learning_rate, "the schedule's peak (Adam)")
      ->check(app_support::number_in(0.0, 1.0, true))
      ->capture_default_str();
  app.add_option("--seed", settings.seed, "of the first weights and of every batch's draw")
      ->check(app_support::any_seed())
      ->capture_default_str();
  app.add_option("--checkpoint-every", settings.checkpoint_every, "steps between checkpoints")
      ->check(app_support::whole_number_in(1, 10000000))
      ->capture_default_str();
  app.add_option("--threads", settings.threads, "0 = all hardware threads")
      ->check(app_support::whole_number_in(0, app_support::kMaxThreadRequest))
      ->capture_default_str();
  app.footer("Exit codes: 0 done, 1 a failure while training, 2 a bad option or input, 130 or 143 interrupted by "
             "Ctrl-C or SIGTERM (the last checkpoint is kept).");
  if (const std::optional<int> exit_code = app_support::parse_command_line(app, argc, argv, "train_denoiser"))
    return *exit_code;
  try {
    if (argc > 1 && (settings.reference.empty() || settings.noisy.empty()))
      throw matbase::InputError("needs --reference and --noisy (or no arguments, for the example)");
    return train(settings, /*example=*/argc == 1);
  } catch (const matbase::InputError& e) {
    return app_support::report_error("train_denoiser", e.what(), app_support::kInputError);
  } catch (const matdataset::DatasetError& e) {
    return app_support::report_error("train_denoiser", e.what(), app_support::kInputError);
  } catch (const std::invalid_argument& e) {
    return app_support::report_error("train_denoiser", e.what(), app_support::kInputError);
  } catch (const std::exception& e) {
    return app_support::report_error("train_denoiser", e.what(), app_support::kRuntimeFailure);
  }
}
