#include "obj/obj_text_screening.h"

#include <algorithm>
#include <cstddef>
#include <string_view>

#include "file_error.h"

namespace matgeom::obj {
namespace {

// Calls visit(begin, end) for every line of `text`, split where tinyobjloader's safeGetline
// splits: at \n, \r\n or \r.
template <typename Visit>
void for_each_line(const std::string& text, Visit visit) {
  size_t begin = 0;
  while (begin < text.size()) {
    size_t end = text.find_first_of("\r\n", begin);
    if (end == std::string::npos) end = text.size();
    visit(begin, end);
    const bool crlf = end + 1 < text.size() && text[end] == '\r' && text[end + 1] == '\n';
    begin = end + (crlf ? 2 : 1);
  }
}

// The keyword a line starts with as tinyobjloader tests keywords: after leading blanks and up to
// the next blank; empty when no blank follows it (tinyobjloader then ignores the line).
std::string_view line_keyword(std::string_view line) {
  const size_t begin = line.find_first_not_of(" \t");
  if (begin == std::string_view::npos) return {};
  const size_t end = line.find_first_of(" \t", begin);
  if (end == std::string_view::npos) return {};
  return line.substr(begin, end - begin);
}

// Blank-separated words after a line's keyword, up to the end of the line or a NUL byte (where
// tinyobjloader's C-string parsing stops).
size_t count_arguments(std::string_view line) {
  line = line.substr(0, line.find('\0'));
  size_t position = line.find_first_not_of(" \t");
  position = line.find_first_of(" \t", position);
  size_t count = 0;
  while (true) {
    position = line.find_first_not_of(" \t", position);
    if (position == std::string_view::npos) return count;
    ++count;
    position = line.find_first_of(" \t", position);
  }
}

// A decimal number as C's strtod reads it without "nan", "inf" or hex: tinyobjloader reads
// anything else as 0 without a word, so "v 1 nan 0" would put the vertex at y = 0.
bool is_decimal_number(std::string_view word) {
  size_t i = 0;
  if (i < word.size() && (word[i] == '+' || word[i] == '-')) ++i;
  const auto digits = [&] {
    const size_t start = i;
    while (i < word.size() && word[i] >= '0' && word[i] <= '9') ++i;
    return i - start;
  };
  size_t mantissa_digits = digits();
  if (i < word.size() && word[i] == '.') {
    ++i;
    mantissa_digits += digits();
  }
  if (mantissa_digits == 0) return false;
  if (i < word.size() && (word[i] == 'e' || word[i] == 'E')) {
    ++i;
    if (i < word.size() && (word[i] == '+' || word[i] == '-')) ++i;
    if (digits() == 0) return false;
  }
  return i == word.size();
}

// The first argument of a line that is not a decimal number, if any.
std::string_view first_non_number(std::string_view line) {
  line = line.substr(0, line.find('\0'));
  size_t position = line.find_first_not_of(" \t");
  position = line.find_first_of(" \t", position);
  while (true) {
    position = line.find_first_not_of(" \t", position);
    if (position == std::string_view::npos) return {};
    const size_t end = std::min(line.find_first_of(" \t", position), line.size());
    const std::string_view word = line.substr(position, end - position);
    if (word.front() == '#') return {};  // a comment ends the line
    if (!is_decimal_number(word)) return word;
    position = end;
  }
}

// tinyobjloader's ear clipping takes time quadratic in a polygon's corners (about 0.2 s for
// 8000 on a star-shaped polygon), so a hostile file could stall the reader for minutes with one
// face; real polygons stay far below this.
constexpr size_t kMaxPolygonCorners = 10000;

// tinyobjloader fills whatever a material leaves out with its own defaults (Ns 1, Ka 0, Pr 0...),
// indistinguishable from written values. Blender's MTL parser (io/wavefront_obj/importer/
// obj_import_file_reader.cc) marks them -1 instead, and its importer then picks defaults that
// depend on illum. Starting every material with these lines makes tinyobjloader report the same
// markers (a value the file gives comes later and replaces its marker).
// The d marker also keeps tinyobjloader from reading Tr as 1 - d: Blender 3.4 ignores Tr.
constexpr const char* kNotGivenMarkers =
    "Ns -1\nKa -1 -1 -1\nKd -1 -1 -1\nKs -1 -1 -1\nPr -1\nPm -1\nNi -1\nd -1\nKe -1 -1 -1\nTf -1 -1 -1\n"
    "Pc -1\nPcr -1\nPs -1\n";

}  // namespace

void screen_obj_text(const std::string& path, std::string& text) {
  size_t line_number = 0;
  for_each_line(text, [&](size_t begin, size_t end) {
    ++line_number;
    const std::string_view line(text.data() + begin, end - begin);
    const std::string_view keyword = line_keyword(line);
    if (keyword == "v" || keyword == "vt" || keyword == "vn") {
      const std::string_view word = first_non_number(line);
      if (!word.empty())
        fail(path, concat("line ", line_number, ": \"", word, "\" in a '", keyword, "' line is not a finite number"));
    }
    if (keyword == "t" || keyword == "vw") {
      std::fill(text.begin() + static_cast<std::ptrdiff_t>(begin),
                text.begin() + static_cast<std::ptrdiff_t>(end), ' ');
      return;
    }
    const size_t corners = keyword == "f" ? count_arguments(line) : 0;
    if (corners > kMaxPolygonCorners) {
      fail(path, concat("a face has ", corners, " corners; more than ", kMaxPolygonCorners,
                        " are refused"));
    }
  });
}

std::string with_not_given_markers(const std::string& text) {
  std::string marked = kNotGivenMarkers;
  for_each_line(text, [&](size_t begin, size_t end) {
    const std::string_view line(text.data() + begin, end - begin);
    const size_t last = line.find_last_not_of(" \t");
    const std::string_view trimmed = line.substr(0, last == std::string_view::npos ? 0 : last + 1);
    if (line_keyword(trimmed) != "newmtl") {
      marked.append(line.data(), line.size()).push_back('\n');
      return;
    }
    // Blender trims material names. tinyobjloader keeps the blanks after the first, and then
    // "usemtl", which reads one word, would miss the material.
    const size_t name = trimmed.find_first_not_of(" \t", trimmed.find("newmtl") + 6);
    marked.append("newmtl ").append(trimmed.substr(name)).append("\n").append(kNotGivenMarkers);
  });
  return marked;
}

}  // namespace matgeom::obj
