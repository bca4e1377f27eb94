#include "matlearn/training/learning_rate_schedule.h"

#include <cmath>
#include <stdexcept>

#include "matbase/pi.h"

namespace matlearn {

ScheduleState start_schedule(double base_rate) {
  ScheduleState state;
  state.rate = base_rate;
  return state;
}

ScheduleState finish_epoch(const ScheduleSettings& settings, double base_rate, ScheduleState state, double loss) {
  state.epochs += 1;
  switch (settings.kind) {
    case ScheduleKind::step:
      // PyTorch's StepLR: base * gamma^floor(epoch / step_size).
      state.rate = base_rate * std::pow(settings.gamma, state.epochs / settings.step_size);
      break;
    case ScheduleKind::cosine: {
      // PyTorch's CosineAnnealingLR closed form (eta_min 0): base (1 + cos(pi t / T_max)) / 2.
      const double pi = matbase::kPi;
      state.rate = 0.5 * base_rate * (1.0 + std::cos(pi * state.epochs / settings.t_max));
      break;
    }
    case ScheduleKind::plateau:
      // PyTorch's ReduceLROnPlateau, mode "min", relative threshold, no cooldown.
      if (!state.has_best || loss < state.best_loss * (1.0 - settings.threshold)) {
        state.best_loss = loss;
        state.has_best = true;
        state.epochs_without_improvement = 0;
      } else if (++state.epochs_without_improvement > settings.patience) {
        state.rate *= settings.gamma;
        state.epochs_without_improvement = 0;
      }
      break;
  }
  return state;
}

ScheduleKind schedule_kind_named(const std::string& name) {
  if (name == "step") return ScheduleKind::step;
  if (name == "cosine") return ScheduleKind::cosine;
  if (name == "plateau") return ScheduleKind::plateau;
  throw std::invalid_argument("unknown learning-rate schedule \"" + name + "\" (step, cosine or plateau)");
}

std::string schedule_kind_name(ScheduleKind kind) {
  switch (kind) {
    case ScheduleKind::step: return "step";
    case ScheduleKind::cosine: return "cosine";
    case ScheduleKind::plateau: return "plateau";
  }
  throw std::logic_error("unknown schedule kind");
}

}  // namespace matlearn
