#pragma once
// Long work that lets Python run meanwhile: the work runs on its own thread without the GIL while
// the calling thread wakes every few milliseconds to take the GIL briefly, report progress to
// Python and look for signals, so other Python threads go on, a progress bar moves, and Ctrl-C
// stops the work promptly with KeyboardInterrupt.
#include <atomic>
#include <functional>

namespace matpredict_python {

// Runs `work` (which must stop soon after `cancel` becomes true), called with the GIL held; on
// each wake, with the GIL held, `report` passes progress to Python. A signal's exception
// (KeyboardInterrupt) or one `report` raises sets `cancel`, waits for the work to stop, and
// propagates; otherwise an exception of the work propagates once it has ended.
void run_releasing_gil(const std::function<void()>& work, std::atomic<bool>& cancel, const std::function<void()>& report);

}  // namespace matpredict_python
