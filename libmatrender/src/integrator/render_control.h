#pragma once
// What the caller sees of a running render (RenderSettings::progress and ::cancel): the fraction
// of sample slots passed (a sample taken, or one a converged pixel skips), reported in batches
// of kProgressSamples per thread, not per tile (at millions of samples per pixel one tile takes
// minutes), serialised and increasing; and a cancel, checked at every packet of samples so that
// it takes effect within milliseconds.
#include <atomic>
#include <cstdint>
#include <functional>
#include <mutex>

#include "matrender/render_settings.h"

namespace matrender {

class RenderControl {
 public:
  static constexpr uint64_t kProgressSamples = 1u << 16;

  // One thread's slots not yet reported.
  struct Batch {
    uint64_t slots = 0;
  };

  RenderControl(const RenderSettings& settings, uint64_t total_slots)
      : progress_(settings.progress), cancel_(settings.cancel), total_slots_(total_slots) {}

  // Whether the render is to stop: the caller's cancel has been seen set.
  bool cancelled() {
    if (cancelled_.load(std::memory_order_relaxed)) return true;
    if (!cancel_ || !cancel_->load(std::memory_order_relaxed)) return false;
    cancelled_ = true;
    return true;
  }
  bool was_cancelled() const { return cancelled_; }

  // `slots` more passed by the thread owning `batch`, reported once the batch is large enough.
  void pass(Batch& batch, uint64_t slots) {
    batch.slots += slots;
    if (batch.slots >= kProgressSamples) report(batch);
  }
  // Reports what `batch` holds (at a tile's end).
  void report(Batch& batch);

 private:
  const std::function<void(double)>& progress_;
  const std::atomic<bool>* cancel_;
  const uint64_t total_slots_;
  std::atomic<uint64_t> passed_{0};
  std::atomic<bool> cancelled_{false};
  std::mutex mutex_;
  double reported_fraction_ = 0.0;
};

inline void RenderControl::report(Batch& batch) {
  const uint64_t done = passed_.fetch_add(batch.slots) + batch.slots;
  batch.slots = 0;
  if (!progress_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  const double fraction = static_cast<double>(done) / static_cast<double>(total_slots_);
  if (fraction <= reported_fraction_) return;
  reported_fraction_ = fraction;
  progress_(fraction);
}

}  // namespace matrender
