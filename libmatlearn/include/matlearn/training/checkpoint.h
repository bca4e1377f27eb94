#pragma once
// A training checkpoint: everything needed to rebuild the network and continue training exactly
// where it stopped (network, output layout, weights and BatchNorm statistics, optimiser moments,
// learning-rate schedule, finished epochs), in one file torch's serialisation writes. Files are
// written under a temporary name and renamed, so a stopped job never leaves half a checkpoint.
#include <filesystem>
#include <memory>
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

// Throws std::runtime_error naming the file when it is not a matpredict checkpoint.
CheckpointHeader read_checkpoint_header(const std::filesystem::path& path);
// A freshly built network of the header's design with the checkpoint's weights.
std::shared_ptr<RegressorImpl> load_checkpoint_model(const std::filesystem::path& path, const CheckpointHeader& header);
// Restores the optimiser state into an optimiser built for `model`'s parameters.
void load_checkpoint_optimizer(const std::filesystem::path& path, torch::optim::Optimizer& optimizer);

}  // namespace matlearn
