#include "interrupt.h"

#include <signal.h>

namespace app_support {
namespace {

// Only lock-free atomics may be touched from a signal handler.
static_assert(std::atomic<bool>::is_always_lock_free);
static_assert(std::atomic<int>::is_always_lock_free);
std::atomic<bool> interrupted{false};
std::atomic<int> interrupting_signal{SIGINT};

void request_cancel(int signal) {
  interrupting_signal.store(signal);
  interrupted.store(true);
}

}  // namespace

const std::atomic<bool>* cancel_on_interrupt() {
  struct sigaction action {};
  action.sa_handler = request_cancel;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND;  // one-shot: the default action is back for a second signal
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  return &interrupted;
}

int interrupted_exit_code() { return 128 + interrupting_signal.load(); }

}  // namespace app_support
