#pragma once
// Training the learned denoiser on pairs make_dataset rendered (denoiser_pairs.h), as Open Image
// Denoise trains its networks (docs/denoising.md, "Training"): random crops of random pairs, Adam,
// and OIDN's "L1 + gradient" loss on the transferred colour. Every checkpoint_every steps the
// network, the optimiser's moments and the step go to <weights>.checkpoint (written under a
// temporary name and renamed), and a run started again continues from there, drawing the same
// batches it would have drawn: a run longer than a session is run in parts.
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <vector>

#include <torch/torch.h>

namespace matlearn {

struct DenoiserTrainingSettings {
  std::filesystem::path reference;           // the frames at many samples
  std::vector<std::filesystem::path> noisy;  // the same frames at few samples, a dataset per count
  std::filesystem::path weights;             // written at every checkpoint and at the end
  int steps = 4000;
  int batch = 8;
  int crop = 128;                 // pixels per side, a multiple of 16
  double learning_rate = 3e-4;    // the schedule's peak (denoiser_learning_rate)
  uint64_t seed = 1;              // of the batches' draws and the first weights
  int checkpoint_every = 50;
  int threads = 0;                // 0 = all hardware threads
};

// The loss of OIDN's "l1 + gradient" choice on transferred values, each term a mean over pixels
// and channels:  0.5 |y - t| + 0.5 (|dx y - dx t| + |dy y - dy t|), dx and dy the differences of
// horizontal and vertical neighbours.
torch::Tensor denoiser_loss(const torch::Tensor& output, const torch::Tensor& target);

// The learning rate at `step` (from 0): a linear warm-up over the first 2 % of the steps to the
// peak, then half a cosine down to 1 % of it at the last step.
double denoiser_learning_rate(const DenoiserTrainingSettings& settings, int step);

// The path of the checkpoint beside `weights`.
std::filesystem::path denoiser_checkpoint_path(const std::filesystem::path& weights);

struct DenoiserTrainingProgress {
  int step = 0;          // steps done
  int steps = 0;         // of
  double loss = 0.0;     // the mean loss of the steps since the last report
  bool resumed = false;  // the run continued from a checkpoint at its first report
};

// Trains (or continues from the checkpoint, refusing one made with other settings) until
// `steps` are done or `cancel` is set, reporting after every checkpoint. Throws
// std::invalid_argument for settings out of range, matdataset::DatasetError naming the file for
// a pair that cannot be read, std::runtime_error naming the checkpoint for one that cannot.
// Returns whether every step is done.
bool train_denoiser(const DenoiserTrainingSettings& settings,
                    const std::function<void(const DenoiserTrainingProgress&)>& report,
                    const std::atomic<bool>* cancel = nullptr);

}  // namespace matlearn
