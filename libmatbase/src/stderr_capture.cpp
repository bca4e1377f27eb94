#include "matbase/stderr_capture.h"

#include <unistd.h>

#include <initializer_list>

namespace matbase {
namespace {

std::mutex& capture_mutex() {
  static std::mutex mutex;
  return mutex;
}

}  // namespace

StandardErrorCapture::StandardErrorCapture() : lock_(capture_mutex()) {
  std::fflush(stderr);
  file_ = std::tmpfile();
  if (!file_) return;
  saved_ = ::dup(STDERR_FILENO);
  if (saved_ < 0 || ::dup2(::fileno(file_), STDERR_FILENO) < 0) {
    if (saved_ >= 0) ::close(saved_);
    saved_ = -1;
    std::fclose(file_);
    file_ = nullptr;
  }
}

StandardErrorCapture::~StandardErrorCapture() { take(); }

std::string StandardErrorCapture::take() {
  if (!file_) return "";
  std::fflush(stderr);
  ::dup2(saved_, STDERR_FILENO);
  ::close(saved_);
  std::string captured;
  std::rewind(file_);
  char buffer[4096];
  for (size_t n; (n = std::fread(buffer, 1, sizeof buffer, file_)) > 0;) captured.append(buffer, n);
  std::fclose(file_);
  file_ = nullptr;
  return captured;
}

std::string pass_on_other_lines(const std::string& captured, std::initializer_list<const char*> library_prefixes) {
  std::string library;
  for (size_t begin = 0; begin < captured.size();) {
    size_t end = captured.find('\n', begin);
    end = end == std::string::npos ? captured.size() : end + 1;
    const std::string line = captured.substr(begin, end - begin);
    bool theirs = false;
    for (const char* prefix : library_prefixes) theirs = theirs || line.rfind(prefix, 0) == 0;
    if (theirs) library += line;
    else std::fputs(line.c_str(), stderr);
    begin = end;
  }
  return library;
}

}  // namespace matbase
