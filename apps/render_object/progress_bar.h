#pragma once
// A render progress bar on stderr with percentage and estimated time left. On a terminal it is
// one line redrawn in place, only when its text changes; when stderr is a file or a pipe (logs,
// CI) it prints a plain line every 10 % instead, so logs stay readable.
#include <chrono>
#include <cstdio>
#include <string>

namespace render_object {

class ProgressBar {
 public:
  explicit ProgressBar(std::FILE* out = stderr);

  // `fraction` in [0, 1], never decreasing (matrender::RenderSettings::progress guarantees it).
  void update(double fraction);
  // Ends the bar's line; call once the render has returned.
  void finish();

 private:
  std::string terminal_line(double fraction, double elapsed) const;

  std::FILE* out_;
  bool terminal_;
  std::chrono::steady_clock::time_point start_;
  std::string last_line_;
  int last_tenth_ = -1;
};

}  // namespace render_object
