#pragma once
// The exit codes every app documents in its --help footer, and the one way they report an error:
// "<program>: <message>" on stderr. Interruptions exit with interrupted_exit_code()
// (common/interrupt.h).
#include <cstdio>
#include <filesystem>
#include <string>

namespace app_support {

constexpr int kRuntimeFailure = 1;  // a render, write or check failed
constexpr int kInputError = 2;      // a bad option or input file

// Prints the message and returns `exit_code`, for `return report_error(...)`.
inline int report_error(const char* program, const std::string& message, int exit_code) {
  std::fprintf(stderr, "%s: %s\n", program, message.c_str());
  return exit_code;
}

// A file system failure as the apps' other errors read, "out/vase: No space left on device",
// not the library's "filesystem error: cannot create directories: ... [out/vase]".
inline std::string filesystem_error_text(const std::filesystem::filesystem_error& e) {
  const std::string path = e.path1().empty() ? std::string("the file system") : e.path1().string();
  return path + ": " + e.code().message();
}

}  // namespace app_support
