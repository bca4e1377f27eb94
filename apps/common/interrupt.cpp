#include "interrupt.h"

#include <signal.h>

namespace app_support {
namespace {

// Only lock-free atomics may be touched from a signal handler.
static_assert(std::atomic<bool>::is_always_lock_free);
std::atomic<bool> interrupted{false};

void request_cancel(int /*signal*/) { interrupted.store(true); }

}  // namespace

const std::atomic<bool>* cancel_on_interrupt() {
  struct sigaction action {};
  action.sa_handler = request_cancel;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND;  // one-shot: the default action is back for a second Ctrl-C
  sigaction(SIGINT, &action, nullptr);
  return &interrupted;
}

}  // namespace app_support
