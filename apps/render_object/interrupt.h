#pragma once
// Ctrl-C during a render: the first SIGINT asks the renderer to stop between tiles, so that the
// app can exit without writing a half-rendered image; a second one ends the process at once.
#include <atomic>

namespace render_object {

// Installs the SIGINT handler and returns the flag it sets (for RenderSettings::cancel).
const std::atomic<bool>* cancel_on_interrupt();

}  // namespace render_object
