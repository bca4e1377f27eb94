#pragma once
// How the file readers and writers report a problem: std::runtime_error("<path>: <problem>").
#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>

#include "matbase/text_encoding.h"

namespace matbase {

// A file's name and bytes may be in any encoding: the message is kept valid UTF-8.
[[noreturn]] inline void fail(const std::string& path, const std::string& problem) {
  throw std::runtime_error(valid_utf8(path + ": " + problem));
}

// The arguments streamed into one string, for messages that mix text and numbers.
template <typename... Args>
std::string concat(const Args&... args) {
  std::ostringstream out;
  (out << ... << args);
  return out.str();
}

// Text from a file for an error message, as written but cut short: a corrupt file can put
// anything where a keyword, a name or a number should be, megabytes of it or control characters
// (shown as \xNN, so that a message stays one readable line), and bytes of another encoding than
// UTF-8 (shown as \xNN too: a message stays valid UTF-8). `most`: the bytes shown, a word's worth
// by default.
inline std::string cut_short(std::string_view text, size_t most = 60) {
  std::string shown;
  const std::string_view kept = text.substr(0, most);
  for (size_t i = 0; i < kept.size();) {
    const auto byte = static_cast<unsigned char>(kept[i]);
    const size_t length = utf8_sequence_length(kept, i);
    if (length > 1 || (length == 1 && byte >= 0x20 && byte != 0x7F)) {
      shown.append(kept.substr(i, length));
      i += length;
      continue;
    }
    char escaped[5];
    std::snprintf(escaped, sizeof escaped, "\\x%02X", byte);
    shown += escaped;
    ++i;
  }
  if (text.size() > most) shown += concat("... (", text.size(), " characters)");
  return shown;
}

// cut_short(text) in quotes: where the text ends stays visible.
inline std::string excerpt(std::string_view text) { return "\"" + cut_short(text) + "\""; }

// A library's message fit to pass on: every data URI in it (a glTF buffer or image can hold
// megabytes of base64, which tinygltf quotes whole) cut after its media type, and the whole cut
// to a few lines.
inline std::string without_data_uris(std::string_view text) {
  constexpr size_t kMaxShown = 600;
  std::string out;
  size_t start = 0;
  for (size_t found; (found = text.find("data:", start)) != std::string_view::npos;) {
    const size_t comma = text.find(',', found);
    const size_t end = text.find_first_of(" \t\r\n\"'", found);
    const size_t stop = end == std::string_view::npos ? text.size() : end;
    if (comma == std::string_view::npos || comma > stop) {
      out.append(text.substr(start, stop - start));
    } else {
      out.append(text.substr(start, comma + 1 - start));
      out += concat("<", stop - comma - 1, " characters of data>");
    }
    start = stop;
  }
  out.append(text.substr(start));
  if (out.size() > kMaxShown) out = out.substr(0, kMaxShown) + concat("... (", out.size(), " characters)");
  return out;
}

}  // namespace matbase
