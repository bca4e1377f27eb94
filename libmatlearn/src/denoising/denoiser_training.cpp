#include "matlearn/denoising/denoiser_training.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "matbase/pi.h"
#include "matbase/threads.h"
#include "matdataset/format/dataset_error.h"
#include "matlearn/denoising/denoiser_pairs.h"
#include "matlearn/denoising/denoising_unet.h"
#include "matlearn/models/state_dict.h"
#include "models/torch_error.h"

namespace matlearn {
namespace {

namespace fs = std::filesystem;

// What a checkpoint must agree with to be continued: everything that shapes the run.
std::string settings_fingerprint(const DenoiserTrainingSettings& s) {
  std::string noisy;
  for (const fs::path& dataset : s.noisy) noisy += fs::absolute(dataset).lexically_normal().string() + ";";
  return fmt::format("steps={} batch={} crop={} learning_rate={} seed={} reference={} noisy={}", s.steps, s.batch, s.crop,
                     s.learning_rate, s.seed, fs::absolute(s.reference).lexically_normal().string(), noisy);
}

void check_settings(const DenoiserTrainingSettings& s) {
  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument("train_denoiser: " + what);
  };
  require(!s.noisy.empty(), "needs at least one noisy dataset");
  require(s.steps >= 1, "steps must be at least 1");
  require(s.batch >= 1 && s.batch <= 1024, "batch must be from 1 to 1024");
  require(s.crop >= kDenoiserSideMultiple && s.crop % kDenoiserSideMultiple == 0 && s.crop <= 4096,
          "crop must be a multiple of 16 from 16 to 4096");
  require(std::isfinite(s.learning_rate) && s.learning_rate > 0.0 && s.learning_rate <= 1.0,
          "learning rate must be in (0, 1]");
  require(s.checkpoint_every >= 1, "checkpoint_every must be at least 1");
  require(!s.weights.empty(), "needs a weights path");
}

// The step's random stream: from the seed and the step alone, so a resumed run draws what the
// uninterrupted one would have.
std::mt19937_64 step_random(uint64_t seed, int step) {
  std::seed_seq sequence{static_cast<uint32_t>(seed), static_cast<uint32_t>(seed >> 32), static_cast<uint32_t>(step)};
  return std::mt19937_64(sequence);
}

// A batch of random crops of random pairs, flipped left-right half of the time: inputs N x 9 x
// crop x crop, targets N x 3 x crop x crop.
std::pair<torch::Tensor, torch::Tensor> draw_batch(const DenoiserTrainingSettings& s,
                                                   const std::vector<matdataset::SampleId>& frames, int step) {
  std::mt19937_64 random = step_random(s.seed, step);
  std::vector<torch::Tensor> inputs, targets;
  for (int b = 0; b < s.batch; ++b) {
    const matdataset::SampleId& id = frames[std::uniform_int_distribution<size_t>(0, frames.size() - 1)(random)];
    const fs::path& noisy = s.noisy[std::uniform_int_distribution<size_t>(0, s.noisy.size() - 1)(random)];
    const DenoiserPair pair = read_denoiser_pair(noisy, s.reference, id);
    const int64_t height = pair.input.size(1), width = pair.input.size(2);
    if (height < s.crop || width < s.crop)
      throw matdataset::DatasetError(fmt::format("{}/{}: its frames are {} x {} pixels, smaller than the {}-pixel crop",
                                                 noisy.string(), id.str(), width, height, s.crop));
    const int64_t y = std::uniform_int_distribution<int64_t>(0, height - s.crop)(random);
    const int64_t x = std::uniform_int_distribution<int64_t>(0, width - s.crop)(random);
    torch::Tensor input = pair.input.narrow(1, y, s.crop).narrow(2, x, s.crop);
    torch::Tensor target = pair.target.narrow(1, y, s.crop).narrow(2, x, s.crop);
    if (std::uniform_int_distribution<int>(0, 1)(random) == 1) {
      input = input.flip({2});
      target = target.flip({2});
    }
    inputs.push_back(input);
    targets.push_back(target);
  }
  return {torch::stack(inputs), torch::stack(targets)};
}

void save_checkpoint(const fs::path& path, const std::string& fingerprint, DenoisingUNet& network,
                     torch::optim::Adam& optimizer, int step) {
  torch::serialize::OutputArchive archive, network_archive, optimizer_archive;
  network->save(network_archive);
  optimizer.save(optimizer_archive);
  archive.write("network", network_archive);
  archive.write("optimizer", optimizer_archive);
  archive.write("step", torch::tensor(static_cast<int64_t>(step)));
  archive.write("settings", c10::IValue(fingerprint));
  const fs::path partial = path.string() + ".partial";
  archive.save_to(partial.string());
  fs::rename(partial, path);
}

// The step the checkpoint at `path` stopped at, its network and optimiser restored.
int load_checkpoint(const fs::path& path, const std::string& fingerprint, DenoisingUNet& network,
                    torch::optim::Adam& optimizer) {
  torch::serialize::InputArchive archive, network_archive, optimizer_archive;
  c10::IValue settings;
  torch::Tensor step;
  try {
    archive.load_from(path.string());
    archive.read("settings", settings);
    archive.read("step", step);
    archive.read("network", network_archive);
    archive.read("optimizer", optimizer_archive);
  } catch (const std::exception& e) {
    throw std::runtime_error(path.string() + ": not a denoiser training checkpoint (" + torch_error_text(e) + ")");
  }
  if (!settings.isString() || settings.toStringRef() != fingerprint)
    throw std::runtime_error(path.string() + ": made by a run with other settings (" +
                             (settings.isString() ? settings.toStringRef() : std::string("none")) +
                             "); delete it to start again, or give the settings it was made with");
  try {
    network->load(network_archive);
    optimizer.load(optimizer_archive);
  } catch (const std::exception& e) {
    throw std::runtime_error(path.string() + ": its network or optimiser does not fit (" + torch_error_text(e) + ")");
  }
  return static_cast<int>(step.item<int64_t>());
}

}  // namespace

torch::Tensor denoiser_loss(const torch::Tensor& output, const torch::Tensor& target) {
  const auto dx = [](const torch::Tensor& t) { return t.narrow(3, 1, t.size(3) - 1) - t.narrow(3, 0, t.size(3) - 1); };
  const auto dy = [](const torch::Tensor& t) { return t.narrow(2, 1, t.size(2) - 1) - t.narrow(2, 0, t.size(2) - 1); };
  const torch::Tensor l1 = (output - target).abs().mean();
  const torch::Tensor gradient = (dx(output) - dx(target)).abs().mean() + (dy(output) - dy(target)).abs().mean();
  return 0.5 * l1 + 0.5 * gradient;
}

double denoiser_learning_rate(const DenoiserTrainingSettings& settings, int step) {
  const int warmup = std::max(1, settings.steps / 50);
  if (step < warmup) return settings.learning_rate * (step + 1) / warmup;
  const double progress = settings.steps > warmup + 1
                              ? static_cast<double>(step - warmup) / static_cast<double>(settings.steps - warmup - 1)
                              : 1.0;
  const double floor = 0.01 * settings.learning_rate;
  return floor + 0.5 * (settings.learning_rate - floor) * (1.0 + std::cos(matbase::kPi * std::min(progress, 1.0)));
}

fs::path denoiser_checkpoint_path(const fs::path& weights) { return weights.string() + ".checkpoint"; }

bool train_denoiser(const DenoiserTrainingSettings& settings,
                    const std::function<void(const DenoiserTrainingProgress&)>& report, const std::atomic<bool>* cancel) {
  check_settings(settings);
  const std::vector<matdataset::SampleId> frames = paired_frames(settings.reference, settings.noisy);
  torch::set_num_threads(matbase::worker_threads(settings.threads));
  torch::manual_seed(settings.seed);
  DenoisingUNet network;
  torch::optim::Adam optimizer(network->parameters(), torch::optim::AdamOptions(settings.learning_rate));
  const std::string fingerprint = settings_fingerprint(settings);
  const fs::path checkpoint = denoiser_checkpoint_path(settings.weights);
  int step = 0;
  bool resumed = false;
  if (fs::exists(checkpoint)) {
    step = load_checkpoint(checkpoint, fingerprint, network, optimizer);
    resumed = true;
  }
  network->train();
  double loss_sum = 0.0;
  int loss_count = 0;
  while (step < settings.steps && !(cancel && cancel->load())) {
    const auto [inputs, targets] = draw_batch(settings, frames, step);
    for (auto& group : optimizer.param_groups())
      static_cast<torch::optim::AdamOptions&>(group.options()).lr(denoiser_learning_rate(settings, step));
    optimizer.zero_grad();
    const torch::Tensor loss = denoiser_loss(network->forward(inputs), targets);
    loss.backward();
    optimizer.step();
    loss_sum += loss.item<double>();
    ++loss_count;
    ++step;
    if (step % settings.checkpoint_every == 0 || step == settings.steps) {
      if (!std::isfinite(loss_sum))
        throw std::runtime_error(fmt::format("train_denoiser: the loss is not finite at step {}; lower the learning rate", step));
      save_checkpoint(checkpoint, fingerprint, network, optimizer, step);
      save_state_dict(*network, settings.weights);
      if (report) report({step, settings.steps, loss_sum / loss_count, resumed});
      loss_sum = 0.0;
      loss_count = 0;
      resumed = false;
    }
  }
  return step >= settings.steps;
}

}  // namespace matlearn
