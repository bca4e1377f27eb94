#pragma once
// What libraries print on standard error while they work, taken instead of shown: libpng prints
// "libpng error: IDAT: Read error" before OpenImageIO reports the same problem, so a refusal would
// reach the user twice, the first time in libpng's words. A capture sends file descriptor 2 to a
// temporary file; one capture runs at a time, process-wide, and whatever another thread writes
// meanwhile is captured too, so callers pass on what is not the library's (pass_on_other_lines).
#include <cstdio>
#include <initializer_list>
#include <mutex>
#include <string>

namespace matbase {

class StandardErrorCapture {
 public:
  StandardErrorCapture();
  ~StandardErrorCapture();  // restores standard error if take() was not called
  StandardErrorCapture(const StandardErrorCapture&) = delete;
  StandardErrorCapture& operator=(const StandardErrorCapture&) = delete;

  // Restores standard error and returns what was written to it since the capture began; "" when
  // it could not be captured (no temporary file), in which case it was shown as usual.
  std::string take();

 private:
  std::unique_lock<std::mutex> lock_;
  std::FILE* file_ = nullptr;
  int saved_ = -1;
};

// Writes to standard error the lines of `captured` that do not start with any of `library_prefixes`
// (the library's own lines, which the caller puts in its message or drops), and returns those.
std::string pass_on_other_lines(const std::string& captured, std::initializer_list<const char*> library_prefixes);

}  // namespace matbase
