#include "common/thread_count.h"

#include <fmt/format.h>

#include "matbase/threads.h"

namespace app_support {

int announced_worker_threads(const std::string& program, const std::string& option, int requested) {
  const int threads = matbase::worker_threads(requested);
  if (requested > threads)
    fmt::print(stderr, "{}: note: {} {} is more than this machine's {} hardware threads; using {}\n", program, option,
               requested, matbase::hardware_threads(), threads);
  return threads;
}

}  // namespace app_support
