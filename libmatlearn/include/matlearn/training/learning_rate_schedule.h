#pragma once
// The paper's three learning-rate schedules, stepped once per epoch: StepLR (step 20, gamma 0.5,
// the default), cosine annealing to 0 over T_max epochs, and reduce-on-plateau of the validation
// loss. Closed forms, so the rate after any number of epochs follows from the state alone and a
// resumed run continues exactly.
#include <string>

namespace matlearn {

enum class ScheduleKind { step, cosine, plateau };

struct ScheduleSettings {
  ScheduleKind kind = ScheduleKind::step;
  int step_size = 20;       // step: epochs between reductions
  double gamma = 0.5;       // step and plateau: the reduction factor
  int t_max = 50;           // cosine: the half period in epochs (the paper's 50)
  int patience = 5;         // plateau: epochs without improvement before reducing
  double threshold = 1e-4;  // plateau: relative improvement that counts (PyTorch's default)
};

// The schedule's state after some epochs; plain values, saved in checkpoints.
struct ScheduleState {
  int epochs = 0;                 // finished epochs
  double rate = 0.0;              // the rate for the next epoch
  double best_loss = 0.0;         // plateau: best validation loss so far
  bool has_best = false;
  int epochs_without_improvement = 0;
};

ScheduleState start_schedule(double base_rate);
// The state after one more epoch whose validation loss (used by plateau only) was `loss`.
ScheduleState finish_epoch(const ScheduleSettings& settings, double base_rate, ScheduleState state, double loss);

ScheduleKind schedule_kind_named(const std::string& name);  // "step", "cosine", "plateau"
std::string schedule_kind_name(ScheduleKind kind);

}  // namespace matlearn
