#pragma once
// Ctrl-C or a scheduler's SIGTERM during long work: the first SIGINT or SIGTERM sets a flag the
// work checks (the renderer at every packet of samples, training between steps), so that the app
// can exit without writing half a result; a second one ends the process at once, after removing
// the temporaries being written (matbase::remove_temporaries_in_flight).
#include <atomic>

namespace app_support {

// Installs the SIGINT and SIGTERM handlers and returns the flag they set (for
// RenderSettings::cancel).
const std::atomic<bool>* cancel_on_interrupt();

// What shells report for the signal that set the flag: 130 for SIGINT, 143 for SIGTERM.
int interrupted_exit_code();

}  // namespace app_support
