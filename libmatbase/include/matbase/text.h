#pragma once
// Small text helpers every library uses for messages and names.
#include <cctype>
#include <filesystem>
#include <string>
#include <string_view>

namespace matbase {

// `text` without leading and trailing spaces, tabs and line breaks.
inline std::string trim(std::string_view text) {
  const size_t begin = text.find_first_not_of(" \t\r\n");
  if (begin == std::string_view::npos) return "";
  return std::string(text.substr(begin, text.find_last_not_of(" \t\r\n") - begin + 1));
}

// `text` in ASCII lower case (file names, extensions, keys compared case-insensitively).
inline std::string lowercase(std::string_view text) {
  std::string lower(text);
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return lower;
}

// The extension of `path` with its dot, in lower case: ".png" for "Wood.PNG".
inline std::string lowercase_extension(const std::filesystem::path& path) {
  return lowercase(path.extension().string());
}

}  // namespace matbase
