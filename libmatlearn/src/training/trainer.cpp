#include "matlearn/training/trainer.h"

#include <chrono>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "matbase/file/atomic_file.h"
#include "matbase/threads.h"
#include "matdataset/format/sample_loader.h"
#include "matlearn/models/state_dict.h"
#include "matlearn/training/batch.h"
#include "matlearn/training/checkpoint.h"
#include "matlearn/training/tensor_memory_cache.h"

namespace matlearn {
namespace {

// SplitMix64's finaliser (Steele, Lea, Flood 2014): a well-mixed seed for every (run, epoch,
// step), so a step's random draws do not depend on the steps before it.
uint64_t mix(uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

uint64_t step_seed(uint64_t seed, int epoch, size_t step) {
  return mix(mix(seed ^ mix(static_cast<uint64_t>(epoch))) ^ static_cast<uint64_t>(step));
}

matdataset::LoaderSettings loader_settings(const TrainingConfig& c, bool shuffle) {
  matdataset::LoaderSettings s;
  s.sample = sample_settings(c.layout, c.image_size, c.linear_albedo);
  s.batch_size = c.batch_size;
  s.shuffle = shuffle;
  s.seed = c.seed;
  s.threads = matbase::worker_threads(c.threads);
  return s;
}

std::unique_ptr<torch::optim::Optimizer> make_optimizer(const TrainingConfig& c, RegressorImpl& model) {
  if (c.optimizer == OptimizerKind::adam)
    return std::make_unique<torch::optim::Adam>(model.parameters(),
                                                torch::optim::AdamOptions(c.learning_rate).weight_decay(c.weight_decay));
  return std::make_unique<torch::optim::AdamW>(model.parameters(),
                                               torch::optim::AdamWOptions(c.learning_rate).weight_decay(c.weight_decay));
}

void validate_config(const TrainingConfig& c) {
  validate(c.layout);
  const ArchitectureInfo& network = architecture_named(c.network);
  if (c.train_samples.empty()) throw std::invalid_argument("no training samples");
  if (c.epochs < 1 || c.batch_size < 1 || c.validate_every < 1)
    throw std::invalid_argument("epochs, batch size and validation interval must be at least 1");
  if (c.threads < 0) throw std::invalid_argument("threads must be >= 0 (0: every hardware thread)");
  if (c.image_size < network.side_multiple || c.image_size % network.side_multiple != 0)
    throw std::invalid_argument(network.name + " needs an image size that is a multiple of " +
                                std::to_string(network.side_multiple) + " (got " + std::to_string(c.image_size) + ")");
  if (!(c.learning_rate > 0.0) || !(c.weight_decay >= 0.0))
    throw std::invalid_argument("the learning rate must be positive and the weight decay not negative");
  if (c.output_dir.empty()) throw std::invalid_argument("no output folder");
}

// That `what` (a loss, a weight) stopped being a number, and the likely cause.
TrainingDiverged diverged(const TrainingConfig& c, double rate, const std::string& what) {
  std::ostringstream cause;
  cause.precision(3);
  cause << what << ": training diverged, most likely because the learning rate " << rate;
  if (c.optimizer == OptimizerKind::adamw && c.weight_decay > 0.0)
    cause << " (with AdamW's weight decay " << c.weight_decay
          << ", which scales every weight by 1 - rate x decay each step)";
  cause << " is too high for this network and data: lower it and train again";
  return TrainingDiverged(cause.str());
}

std::string csv_row(const EpochReport& r) {
  std::ostringstream row;
  row.precision(9);
  row << r.epoch << ',' << r.train_loss;
  for (double term : r.train_group_terms) row << ',' << term;
  row << ',' << r.train_material_term << ',';
  if (r.validated) row << r.validation_loss;
  row << ',' << r.learning_rate << ',' << r.seconds;
  return row.str();
}

std::string csv_header(const OutputLayout& layout) {
  std::string header = "epoch,train_loss";
  for (const OutputGroup& g : layout.groups) header += ",train_" + map_name(g.map);
  return header + ",train_material,validation_loss,learning_rate,seconds";
}

}  // namespace

Trainer::Trainer(TrainingConfig config) : config_(std::move(config)) {
  validate_config(config_);
  use_tensor_memory_cache();
  torch::set_num_threads(matbase::worker_threads(config_.threads));
  torch::manual_seed(config_.seed);
  model_ = make_regressor(architecture_named(config_.network).architecture, config_.layout.output_channels(),
                          config_.width_divisor);
  if (!config_.encoder_weights.empty()) {
    if (!model_->encoder())
      throw std::invalid_argument(config_.network + " has no pretrainable trunk for " + config_.encoder_weights.string());
    load_state_dict(*model_->encoder(), config_.encoder_weights);
  }
  optimizer_ = make_optimizer(config_, *model_);
  schedule_ = start_schedule(config_.learning_rate);
  // Every map the network needs, before the first step: an epoch never stops on a missing file.
  std::vector<matdataset::SampleId> samples = config_.train_samples;
  samples.insert(samples.end(), config_.validation_samples.begin(), config_.validation_samples.end());
  matdataset::require_sample_files(config_.dataset_root, samples, loader_settings(config_, false).sample,
                                   "the training and validation samples of " + config_.dataset_root.string());
}

void Trainer::resume(const std::filesystem::path& path) {
  const Checkpoint checkpoint = read_checkpoint(path);
  const CheckpointHeader& header = checkpoint.header;
  if (header.network != config_.network || header.width_divisor != config_.width_divisor ||
      header.image_size != config_.image_size)
    throw std::invalid_argument(path.string() + " holds " + header.network + " (widths / " +
                                std::to_string(header.width_divisor) + ") at " + std::to_string(header.image_size) +
                                " px, not the configured " + config_.network + " (widths / " +
                                std::to_string(config_.width_divisor) + ") at " + std::to_string(config_.image_size) +
                                " px");
  // The same channel count is not enough: base_color,normal and base_color,roughness:3 are both 6.
  if (!same_channels(header.layout, config_.layout) || header.linear_albedo != config_.linear_albedo)
    throw std::invalid_argument(path.string() + " was trained to predict " + describe(header.layout) +
                                (header.linear_albedo ? " (linear albedo)" : "") + ", not the configured " +
                                describe(config_.layout) + (config_.linear_albedo ? " (linear albedo)" : ""));
  model_ = load_model(checkpoint);
  optimizer_ = make_optimizer(config_, *model_);
  load_optimizer(checkpoint, *optimizer_);
  schedule_ = header.schedule;
  epochs_done_ = header.epochs_done;
  has_best_ = header.has_best_validation;
  best_validation_loss_ = header.best_validation_loss;
  // The log rows of the epochs the checkpoint holds; later ones belong to a run that went on.
  log_rows_.clear();
  std::ifstream log(log_path());
  std::string row;
  std::getline(log, row);
  while (std::getline(log, row) && static_cast<int>(log_rows_.size()) < epochs_done_) log_rows_.push_back(row);
}

double Trainer::validation_loss() {
  if (config_.validation_samples.empty()) return 0.0;
  const matdataset::SampleLoader loader(config_.dataset_root, config_.validation_samples, loader_settings(config_, false));
  const InputNormalization normalization = info(architecture_named(config_.network).architecture).input_normalization;
  model_->eval();
  torch::NoGradGuard no_grad;
  double weighted = 0.0;
  for (size_t b = 0; b < loader.batch_count(); ++b) {
    const Batch batch = make_batch(loader.batch(0, b), config_.layout, normalization);
    const LossTerms terms = training_loss(model_->forward(batch.input), batch, config_.layout, config_.loss);
    weighted += terms.total.item<double>() * static_cast<double>(batch.input.size(0));
  }
  model_->train();
  return weighted / static_cast<double>(loader.sample_count());
}

void Trainer::require_finite_weights(int epoch) const {
  if (const std::optional<std::string> tensor = first_non_finite_tensor(*model_))
    throw diverged(config_, schedule_.rate,
                   "after epoch " + std::to_string(epoch) + " the weight " + *tensor + " holds a NaN or an infinity");
}

void Trainer::append_log(const EpochReport& report) {
  log_rows_.push_back(csv_row(report));
  std::filesystem::create_directories(config_.output_dir);
  std::string text = csv_header(config_.layout) + '\n';
  for (const std::string& row : log_rows_) text += row + '\n';
  matbase::write_file_atomically(log_path(), text);
}

bool Trainer::train(const TrainingCallbacks& callbacks) {
  const matdataset::SampleLoader loader(config_.dataset_root, config_.train_samples, loader_settings(config_, true));
  const InputNormalization normalization = info(architecture_named(config_.network).architecture).input_normalization;
  const size_t steps = loader.batch_count();
  model_->train();
  while (epochs_done_ < config_.epochs) {
    const int epoch = epochs_done_ + 1;
    const auto start = std::chrono::steady_clock::now();
    for (auto& group : optimizer_->param_groups()) group.options().set_lr(schedule_.rate);
    EpochReport report;
    report.epoch = epoch;
    report.learning_rate = schedule_.rate;
    report.train_group_terms.assign(config_.layout.groups.size(), 0.0);
    double samples_seen = 0.0;
    for (size_t step = 0; step < steps; ++step) {
      if (callbacks.cancel && callbacks.cancel->load()) return false;
      const Batch batch = make_batch(loader.batch(epoch - 1, step), config_.layout, normalization);
      torch::manual_seed(step_seed(config_.seed, epoch, step));
      optimizer_->zero_grad();
      const LossTerms terms = training_loss(model_->forward(batch.input), batch, config_.layout, config_.loss);
      const double loss = terms.total.item<double>();
      // Checked before the step, which would spread the NaN into every weight.
      if (!std::isfinite(loss))
        throw diverged(config_, schedule_.rate,
                       "the loss of epoch " + std::to_string(epoch) + ", batch " + std::to_string(step + 1) + " of " +
                           std::to_string(steps) + " is " + std::to_string(loss));
      terms.total.backward();
      optimizer_->step();
      const double n = static_cast<double>(batch.input.size(0));
      report.train_loss += loss * n;
      for (size_t g = 0; g < terms.group_terms.size(); ++g) report.train_group_terms[g] += terms.group_terms[g] * n;
      report.train_material_term += terms.material_term * n;
      samples_seen += n;
      if (callbacks.step) callbacks.step(epoch, step + 1, steps, loss);
    }
    report.train_loss /= samples_seen;
    for (double& term : report.train_group_terms) term /= samples_seen;
    report.train_material_term /= samples_seen;
    report.validated = !config_.validation_samples.empty() &&
                       (epoch % config_.validate_every == 0 || epoch == config_.epochs);
    require_finite_weights(epoch);
    if (report.validated) report.validation_loss = validation_loss();
    if (!std::isfinite(report.validation_loss))
      throw diverged(config_, schedule_.rate,
                     "the validation loss of epoch " + std::to_string(epoch) + " is " +
                         std::to_string(report.validation_loss));
    // Plateau follows the validation loss, or the training loss when there is no validation.
    schedule_ = finish_epoch(config_.schedule, config_.learning_rate, schedule_,
                             report.validated ? report.validation_loss : report.train_loss);
    epochs_done_ = epoch;
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    CheckpointHeader header;
    header.network = config_.network;
    header.width_divisor = config_.width_divisor;
    header.layout = config_.layout;
    header.image_size = config_.image_size;
    header.linear_albedo = config_.linear_albedo;
    header.epochs_done = epochs_done_;
    header.schedule = schedule_;
    header.config_text = config_.config_text;
    const bool improved = report.validated && (!has_best_ || report.validation_loss < best_validation_loss_);
    if (improved) {
      has_best_ = true;
      best_validation_loss_ = report.validation_loss;
    }
    header.has_best_validation = has_best_;
    header.best_validation_loss = best_validation_loss_;
    const std::filesystem::path checkpoints = config_.output_dir / "checkpoints";
    save_checkpoint(checkpoints / "last.pt", header, *model_, *optimizer_);
    if (improved) save_checkpoint(checkpoints / "best.pt", header, *model_, *optimizer_);
    append_log(report);
    history_.push_back(report);
    if (callbacks.epoch_finished) callbacks.epoch_finished(report);
  }
  return true;
}

OptimizerKind optimizer_kind_named(const std::string& name) {
  if (name == "adam") return OptimizerKind::adam;
  if (name == "adamw") return OptimizerKind::adamw;
  throw std::invalid_argument("unknown optimiser \"" + name + "\" (adam or adamw)");
}

std::string optimizer_kind_name(OptimizerKind kind) { return kind == OptimizerKind::adam ? "adam" : "adamw"; }

}  // namespace matlearn
