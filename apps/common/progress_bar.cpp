#include "progress_bar.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <unistd.h>

#include <fmt/format.h>

namespace app_support {
namespace {

constexpr int kBarWidth = 30;

std::string clock_time(double seconds) {
  const long total = std::lround(seconds);
  if (total >= 3600) return fmt::format("{}:{:02d}:{:02d}", total / 3600, (total / 60) % 60, total % 60);
  return fmt::format("{}:{:02d}", total / 60, total % 60);
}

// Time left if the rest goes as fast as what is done; unknown before anything is done.
std::string eta(double fraction, double elapsed) {
  if (fraction <= 0.0) return "ETA --:--";
  if (fraction >= 1.0) return "done in " + clock_time(elapsed);
  return "ETA " + clock_time(elapsed * (1.0 - fraction) / fraction);
}

}  // namespace

ProgressBar::ProgressBar(std::string label, std::FILE* out)
    : label_(std::move(label)), out_(out), terminal_(::isatty(::fileno(out)) == 1), start_(std::chrono::steady_clock::now()) {}

std::string ProgressBar::terminal_line(double fraction, double elapsed, const std::string& detail) const {
  const int filled = static_cast<int>(fraction * kBarWidth);
  return fmt::format("{} [{}{}] {:3d}%  {}{}{}", label_, std::string(static_cast<size_t>(filled), '#'),
                     std::string(static_cast<size_t>(kBarWidth - filled), '.'),
                     static_cast<int>(fraction * 100.0), eta(fraction, elapsed), detail.empty() ? "" : "  ", detail);
}

void ProgressBar::update(double fraction, const std::string& detail) {
  fraction = std::clamp(fraction, 0.0, 1.0);
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (terminal_) {
    std::string line = terminal_line(fraction, elapsed, detail);
    if (line == last_line_) return;
    // "\r" returns to the line start, "\x1b[K" clears what a longer previous line left behind.
    std::fprintf(out_, "\r%s\x1b[K", line.c_str());
    last_line_ = std::move(line);
  } else {
    const int tenth = static_cast<int>(fraction * 10.0);
    if (tenth == last_tenth_) return;
    std::fprintf(out_, "%s %3d%%  %s%s%s\n", label_.c_str(), tenth * 10, eta(fraction, elapsed).c_str(),
                 detail.empty() ? "" : "  ", detail.c_str());
    last_tenth_ = tenth;
  }
  std::fflush(out_);
}

void ProgressBar::finish() {
  if (terminal_ && !last_line_.empty()) std::fputc('\n', out_);
  std::fflush(out_);
}

}  // namespace app_support
