#pragma once
// A training checkpoint: everything needed to rebuild the network and continue training exactly
// where it stopped (network, output layout, weights and BatchNorm statistics, optimiser moments,
// learning-rate schedule, finished epochs), in one file torch's serialisation writes. Files are
// written under a temporary name and renamed, so a stopped job never leaves half a checkpoint,
// and carry a CRC-32 of everything they hold, so a damaged one is refused instead of scored.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include <torch/torch.h>

#include "matlearn/models/regressor.h"
#include "matlearn/training/learning_rate_schedule.h"
#include "matlearn/training/output_layout.h"

namespace matlearn {

// What a checkpoint says about the network and the run.
struct CheckpointHeader {
  std::string network;  // an ArchitectureInfo name
  int64_t width_divisor = 1;
  OutputLayout layout;
  int image_size = 224;
  bool linear_albedo = false;  // the albedo target was decoded to linear values
  int epochs_done = 0;
  ScheduleState schedule;
  double best_validation_loss = 0.0;  // meaningful when has_best_validation
  bool has_best_validation = false;
  std::string config_text;  // the full training settings (YAML), for the record
};

void save_checkpoint(const std::filesystem::path& path, const CheckpointHeader& header, RegressorImpl& model,
                     torch::optim::Optimizer& optimizer);

// A checkpoint file read whole and verified: its header, and the network's and the optimiser's
// state still serialised (uint8 tensors holding torch archives).
struct Checkpoint {
  std::filesystem::path path;
  CheckpointHeader header;
  torch::Tensor model_state;
  torch::Tensor optimizer_state;
};

// Throws std::runtime_error naming the file when it is not a matpredict checkpoint, when its
// checksum does not match its contents, or when its header describes no network this build has.
Checkpoint read_checkpoint(const std::filesystem::path& path);
// A freshly built network of the header's design with the checkpoint's weights; throws
// std::runtime_error naming the file when the weights do not fit that design or hold a NaN or an
// infinity (a diverged training's, which every prediction would carry).
std::shared_ptr<RegressorImpl> load_model(const Checkpoint& checkpoint);

// The name of the first parameter or buffer (BatchNorm's statistics) of `module` that holds a
// NaN or an infinity, if any.
std::optional<std::string> first_non_finite_tensor(const torch::nn::Module& module);
// Restores the optimiser state into an optimiser built for load_model's parameters.
void load_optimizer(const Checkpoint& checkpoint, torch::optim::Optimizer& optimizer);

}  // namespace matlearn
