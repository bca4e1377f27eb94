#pragma once
// Small text helpers every library uses for messages and names.
#include <string>
#include <string_view>

namespace matgeom {

// `text` without leading and trailing spaces, tabs and line breaks.
inline std::string trim(std::string_view text) {
  const size_t begin = text.find_first_not_of(" \t\r\n");
  if (begin == std::string_view::npos) return "";
  return std::string(text.substr(begin, text.find_last_not_of(" \t\r\n") - begin + 1));
}

}  // namespace matgeom
