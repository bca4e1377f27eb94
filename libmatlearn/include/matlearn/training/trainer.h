#pragma once
// Training a regressor on a MatPredict dataset: the paper's protocol (Adam 2e-4, or AdamW 1e-4
// with weight decay 1e-2; StepLR 20 / 0.5, cosine or plateau; 50 epochs of batch 8) and the
// repository's checkpoints, made resumable exactly: the batch order depends on seed and epoch
// only (SampleLoader), each step reseeds torch's generator from (seed, epoch, step) for the
// stochastic depth it draws, and a checkpoint holds the optimiser moments and the schedule.
// A resumed run therefore computes what the uninterrupted run would have, with the same thread
// count (oneDNN's reductions may differ between thread counts).
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <torch/torch.h>

#include "matdataset/format/dataset_index.h"
#include "matlearn/models/regressor.h"
#include "matlearn/training/learning_rate_schedule.h"
#include "matlearn/training/loss.h"
#include "matlearn/training/output_layout.h"

namespace matlearn {

enum class OptimizerKind { adam, adamw };

struct TrainingConfig {
  std::filesystem::path dataset_root;
  std::vector<matdataset::SampleId> train_samples, validation_samples;
  std::string network = "unet_no_skip";
  int64_t width_divisor = 1;
  std::filesystem::path encoder_weights;  // converted torchvision weights for the trunk, optional
  OutputLayout layout = OutputLayout::paper();
  RegressionLoss loss = RegressionLoss::mse;
  bool linear_albedo = false;  // supervise the albedo decoded to linear values (W5)
  OptimizerKind optimizer = OptimizerKind::adam;
  double learning_rate = 2e-4;
  double weight_decay = 0.0;
  ScheduleSettings schedule;
  int epochs = 50;
  int batch_size = 8;
  int image_size = 224;
  int threads = 0;  // torch and decoding threads; 0 = all hardware threads
  uint64_t seed = 42;
  int validate_every = 1;  // epochs; the last epoch is always validated
  std::filesystem::path output_dir;
  std::string config_text;  // stored in checkpoints for the record
};

struct EpochReport {
  int epoch = 0;  // 1-based
  double train_loss = 0.0;
  std::vector<double> train_group_terms;
  double train_material_term = 0.0;
  bool validated = false;
  double validation_loss = 0.0;
  double learning_rate = 0.0;  // the rate this epoch trained with
  double seconds = 0.0;
};

struct TrainingCallbacks {
  // After every step: epoch (1-based), finished steps in the epoch, steps per epoch, step loss.
  std::function<void(int, size_t, size_t, double)> step;
  std::function<void(const EpochReport&)> epoch_finished;
  const std::atomic<bool>* cancel = nullptr;  // checked between steps; stops without a checkpoint
};

// Training stopped because its loss or its weights stopped being finite numbers. No checkpoint
// of that epoch was written: checkpoints/last.pt, if any, still holds the last finished epoch.
struct TrainingDiverged : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class Trainer {
 public:
  // Builds the network (seeded), loads encoder weights if given, and the optimiser; makes
  // matlearn's tensor memory cache libtorch's CPU allocator (training/tensor_memory_cache.h).
  // Throws std::invalid_argument for a bad configuration, DatasetError naming the files when
  // the samples lack a map the network needs (require_sample_files).
  explicit Trainer(TrainingConfig config);
  // Continues from a checkpoint that train() wrote with the same design.
  void resume(const std::filesystem::path& checkpoint);
  // Trains the remaining epochs. Writes into output_dir: checkpoints/last.pt after every epoch,
  // checkpoints/best.pt when the validation loss improves, and log.csv (one row per epoch; a
  // resumed run keeps the rows of the epochs its checkpoint holds). Returns false if cancelled.
  // Throws TrainingDiverged, naming the epoch (and batch), when a training loss, the weights
  // after an epoch or a validation loss hold a NaN or an infinity, and DatasetError when a
  // sample cannot be read.
  bool train(const TrainingCallbacks& callbacks = {});

  RegressorImpl& model() { return *model_; }
  int epochs_done() const { return epochs_done_; }
  const std::vector<EpochReport>& history() const { return history_; }

 private:
  double validation_loss();
  // Throws TrainingDiverged when a weight after epoch `epoch` is not finite: a step whose loss
  // was finite can still overflow its gradients.
  void require_finite_weights(int epoch) const;
  void append_log(const EpochReport& report);
  std::filesystem::path log_path() const { return config_.output_dir / "log.csv"; }

  TrainingConfig config_;
  std::shared_ptr<RegressorImpl> model_;
  std::unique_ptr<torch::optim::Optimizer> optimizer_;
  ScheduleState schedule_;
  int epochs_done_ = 0;
  bool has_best_ = false;
  double best_validation_loss_ = 0.0;
  std::vector<EpochReport> history_;   // the epochs this process trained
  std::vector<std::string> log_rows_;  // log.csv without its header, one row per finished epoch
};

OptimizerKind optimizer_kind_named(const std::string& name);  // "adam", "adamw"
std::string optimizer_kind_name(OptimizerKind kind);

}  // namespace matlearn
