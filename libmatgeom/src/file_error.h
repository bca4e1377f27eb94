#pragma once
// How the file readers and writers report a problem: std::runtime_error("<path>: <problem>").
#include <sstream>
#include <stdexcept>
#include <string>

namespace matgeom {

[[noreturn]] inline void fail(const std::string& path, const std::string& problem) {
  throw std::runtime_error(path + ": " + problem);
}

// The arguments streamed into one string, for messages that mix text and numbers.
template <typename... Args>
std::string concat(const Args&... args) {
  std::ostringstream out;
  (out << ... << args);
  return out.str();
}

}  // namespace matgeom
