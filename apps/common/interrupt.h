#pragma once
// Ctrl-C during long work: the first SIGINT sets a flag the work checks (the renderer between
// tiles, training between steps), so that the app can exit without writing half a result; a
// second one ends the process at once.
#include <atomic>

namespace app_support {

// Installs the SIGINT handler and returns the flag it sets (for RenderSettings::cancel).
const std::atomic<bool>* cancel_on_interrupt();

}  // namespace app_support
