#pragma once
// How many worker threads a request for `requested` gets, the one rule every library follows.
// Threads beyond the machine's only slow work down (a 0.9 s training epoch took over 60 s with
// 1000), and results never depend on the count, so a larger request is capped.

namespace matbase {

// The most threads any tool or library setting accepts (a larger number is a typo, not a request).
constexpr int kMaxThreadRequest = 65536;

// std::thread::hardware_concurrency(), at least 1.
int hardware_threads();

// 0 means every hardware thread; more than the machine has is capped to it. Throws
// std::invalid_argument for a negative request.
int worker_threads(int requested);

}  // namespace matbase
