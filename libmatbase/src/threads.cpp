#include "matbase/threads.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <thread>

namespace matbase {

int hardware_threads() { return static_cast<int>(std::max(1u, std::thread::hardware_concurrency())); }

int worker_threads(int requested) {
  if (requested < 0) throw std::invalid_argument("thread count must be >= 0, got " + std::to_string(requested));
  return requested == 0 ? hardware_threads() : std::min(requested, hardware_threads());
}

}  // namespace matbase
