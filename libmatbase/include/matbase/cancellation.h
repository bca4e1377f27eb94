#pragma once
// Long work stops when asked: a library material's maps, for one, poll a flag that an app's
// SIGINT or SIGTERM handler sets, and throw Cancelled, which the app reports as an interruption
// (its own exit code, nothing half-written). Polled once a row, a request is acted on in
// milliseconds instead of after the whole material (up to a minute at 8192 texels).
#include <atomic>
#include <stdexcept>

namespace matbase {

struct Cancelled : std::runtime_error {
  Cancelled() : std::runtime_error("cancelled") {}
};

// Throws Cancelled when `cancel` is given and set.
inline void throw_if_cancelled(const std::atomic<bool>* cancel) {
  if (cancel && cancel->load(std::memory_order_relaxed)) throw Cancelled();
}

}  // namespace matbase
