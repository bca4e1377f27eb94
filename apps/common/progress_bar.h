#pragma once
// A progress bar on stderr with a label, percentage, estimated time left and an optional detail
// (a training loss, say). On a terminal it is one line redrawn in place, only when its text
// changes; when stderr is a file or a pipe (logs, CI) it prints a plain line every 10 % instead,
// so logs stay readable.
#include <chrono>
#include <cstdio>
#include <string>

namespace app_support {

class ProgressBar {
 public:
  explicit ProgressBar(std::string label, std::FILE* out = stderr);

  // `fraction` in [0, 1], never decreasing (matrender::RenderSettings::progress guarantees it);
  // `detail` follows the time estimate.
  void update(double fraction, const std::string& detail = {});
  // Ends the bar's line; call once the work has finished.
  void finish();

 private:
  std::string terminal_line(double fraction, double elapsed, const std::string& detail) const;

  std::string label_;
  std::FILE* out_;
  bool terminal_;
  std::chrono::steady_clock::time_point start_;
  std::string last_line_;
  int last_tenth_ = -1;
};

}  // namespace app_support
