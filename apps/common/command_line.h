#pragma once
// Parsing an app's command line, the same way in every app: --help prints and exits 0, and a bad
// option is a bad input, "<program>: <what CLI11 found>" and exit 2 (CLI11's own codes run past
// 100).
#include <optional>

#include <CLI/CLI.hpp>

#include "common/exit_codes.h"

namespace app_support {

// The exit code to end with, or nothing when the app goes on.
inline std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv, const char* program) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    return report_error(program, e.what(), kInputError);
  }
  return std::nullopt;
}

}  // namespace app_support
