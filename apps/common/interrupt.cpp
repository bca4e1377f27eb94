#include "interrupt.h"

#include <signal.h>

#include "matbase/file/atomic_file.h"

namespace app_support {
namespace {

// Only lock-free atomics may be touched from a signal handler.
static_assert(std::atomic<bool>::is_always_lock_free);
static_assert(std::atomic<int>::is_always_lock_free);
std::atomic<bool> interrupted{false};
std::atomic<int> interrupting_signal{SIGINT};

// The first signal asks the work to stop where it can; a second one ends the process at once,
// removing the temporaries being written first, so that even then nothing half-written is left.
void on_signal(int signal) {
  if (interrupted.load()) {
    matbase::remove_temporaries_in_flight();
    ::signal(signal, SIG_DFL);
    ::raise(signal);
    return;
  }
  interrupting_signal.store(signal);  // before the flag, so that whoever sees the flag sees it
  interrupted.store(true);
}

}  // namespace

const std::atomic<bool>* cancel_on_interrupt() {
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  return &interrupted;
}

int interrupted_exit_code() { return 128 + interrupting_signal.load(); }

}  // namespace app_support
