#include "matrender/denoiser.h"

#include <mutex>
#include <stdexcept>

#include "matrender/atrous_filter.h"

namespace matrender {
namespace {

// The one learned denoiser of the process: set by the program, read by every render.
struct LearnedDenoiserSlot {
  std::mutex mutex;
  std::shared_ptr<const Denoiser> denoiser;
};

LearnedDenoiserSlot& learned_slot() {
  static LearnedDenoiserSlot slot;
  return slot;
}

}  // namespace

void provide_learned_denoiser(std::shared_ptr<const Denoiser> denoiser) {
  LearnedDenoiserSlot& slot = learned_slot();
  const std::lock_guard<std::mutex> lock(slot.mutex);
  slot.denoiser = std::move(denoiser);
}

std::shared_ptr<const Denoiser> learned_denoiser() {
  LearnedDenoiserSlot& slot = learned_slot();
  const std::lock_guard<std::mutex> lock(slot.mutex);
  return slot.denoiser;
}

std::optional<std::string> denoising_problem(Denoising denoising) {
  if (denoising != Denoising::Learned || learned_denoiser()) return std::nullopt;
  return "\"learned\" needs the learned denoiser, and this program was built without it (libmatlearn); use "
         "\"filter\" or false";
}

std::shared_ptr<const Denoiser> denoiser_for(Denoising denoising) {
  switch (denoising) {
    case Denoising::Off: return nullptr;
    case Denoising::Filter: {
      static const std::shared_ptr<const Denoiser> filter = std::make_shared<AtrousFilter>();
      return filter;
    }
    case Denoising::Learned:
      if (std::shared_ptr<const Denoiser> learned = learned_denoiser()) return learned;
      throw std::invalid_argument("denoise: " + *denoising_problem(denoising));
  }
  return nullptr;
}

}  // namespace matrender
