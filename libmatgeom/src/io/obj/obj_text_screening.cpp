#include "io/obj/obj_text_screening.h"

#include <algorithm>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "matbase/file/file_error.h"
#include "io/obj/material_names.h"
#include "io/obj/statement_text.h"

namespace matgeom::obj {
namespace {

// tinyobjloader's ear clipping takes time quadratic in a polygon's corners (about 0.2 s for
// 8000 on a star-shaped polygon), so a hostile file could stall the reader for minutes with one
// face; real polygons stay far below this.
constexpr size_t kMaxPolygonCorners = 10000;

[[noreturn]] void fail_at(const std::string& path, size_t line, const std::string& problem) {
  matbase::fail(path, matbase::concat("line ", line, ": ", problem));
}

// The vertex statements so far: OBJ's indices count from the first (1) or back from the last
// (-1) of those that come before the face.
struct VertexCounts {
  int64_t positions = 0;
  int64_t uvs = 0;
  int64_t normals = 0;
};

// The numbers each vertex statement takes: "v x y z [w]" (or "v x y z r g b", tinyobjloader's
// colour extension), "vt u [v [w]]", "vn x y z". tinyobjloader fills a missing one with 0.
const char* vertex_numbers_needed(std::string_view keyword, size_t count) {
  if (keyword == "v") return count == 3 || count == 4 || count == 6 ? nullptr : "x y z (and w, or r g b)";
  if (keyword == "vt") return count >= 1 && count <= 3 ? nullptr : "u and optionally v and w";
  return count == 3 ? nullptr : "x y z";
}

void check_vertex_statement(const std::string& path, size_t line_number, std::string_view keyword,
                            std::string_view line) {
  const std::vector<std::string_view> numbers = statement_arguments(line);
  for (const std::string_view word : numbers) {
    if (!finite_number(word))
      fail_at(path, line_number, matbase::concat(matbase::excerpt(word), " in a '", keyword, "' line is not a finite number"));
  }
  if (const char* needed = vertex_numbers_needed(keyword, numbers.size()))
    fail_at(path, line_number,
            matbase::concat("a '", keyword, "' line takes ", needed, "; this one has ", numbers.size(), " numbers"));
}

bool is_integer_text(std::string_view word) {
  if (!word.empty() && (word.front() == '+' || word.front() == '-')) word.remove_prefix(1);
  return !word.empty() && std::all_of(word.begin(), word.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// Where a corner is, for messages: its line, its statement ("face") and the corner as written,
// named after the problem ("<path>: face index out of range: ... (line 4, corner "1/9")", the
// form messages took when tinyobjloader's indices were checked after it).
struct CornerPlace {
  const std::string& path;
  size_t line;
  const char* statement;
  std::string_view corner;

  [[noreturn]] void fail_here(const std::string& problem) const {
    matbase::fail(path, matbase::concat(problem, " (line ", line, ", corner ", matbase::excerpt(corner), ")"));
  }
};

// One index of a corner as written, against the `count` vertices of its kind before the line.
void check_index(const CornerPlace& place, std::string_view index, int64_t count, const char* kind) {
  if (!is_integer_text(index)) place.fail_here(matbase::concat(place.statement, " index ", matbase::excerpt(index), " is not a whole number"));
  const std::optional<int64_t> value = integer_number(index);  // none beyond 64 bits
  if (value == 0) place.fail_here(matbase::concat(place.statement, " index 0: indices count from 1, or back from -1"));
  if (!value || *value > count || *value < -count) {
    place.fail_here(matbase::concat(place.statement, " index out of range: ", kind, " ", matbase::cut_short(index), " but the file has ",
                           count, " before this line"));
  }
}

// A corner of a face, line or point: v, v/vt, v//vn or v/vt/vn.
void check_corner(const CornerPlace& place, const VertexCounts& counts) {
  std::vector<std::string_view> parts;
  for (size_t begin = 0;;) {
    const size_t slash = place.corner.find('/', begin);
    parts.push_back(place.corner.substr(begin, slash == std::string_view::npos ? std::string_view::npos : slash - begin));
    if (slash == std::string_view::npos) break;
    begin = slash + 1;
  }
  if (parts.size() > 3 || parts.front().empty() || parts.back().empty())
    place.fail_here(matbase::concat("a ", place.statement, " corner is v, v/vt, v//vn or v/vt/vn"));
  check_index(place, parts[0], counts.positions, "position");
  if (parts.size() >= 2 && !parts[1].empty()) check_index(place, parts[1], counts.uvs, "texture coordinate");
  if (parts.size() == 3) check_index(place, parts[2], counts.normals, "normal");
}

// What each statement of corners makes, for messages.
const char* element_name(std::string_view keyword) { return keyword == "f" ? "face" : keyword == "l" ? "line" : "point"; }

void check_element_statement(const std::string& path, size_t line_number, std::string_view keyword,
                             std::string_view line, const VertexCounts& counts) {
  const std::vector<std::string_view> corners = statement_arguments(line);
  const size_t needed = keyword == "f" ? 3 : 1;
  if (corners.size() < needed)
    fail_at(path, line_number,
            matbase::concat("a '", keyword, "' line needs ", needed, " or more corners; this one has ", corners.size()));
  if (keyword == "f" && corners.size() > kMaxPolygonCorners)
    fail_at(path, line_number,
            matbase::concat("a face has ", corners.size(), " corners; more than ", kMaxPolygonCorners, " are refused"));
  for (const std::string_view corner : corners) check_corner({path, line_number, element_name(keyword), corner}, counts);
}

// Where a comment starts in a line ('#' at the start of a word), or the line's size.
size_t comment_start(std::string_view line) {
  for (size_t i = line.find('#'); i != std::string_view::npos; i = line.find('#', i + 1)) {
    if (i == 0 || line[i - 1] == ' ' || line[i - 1] == '\t') return i;
  }
  return line.size();
}

void blank(std::string& text, size_t begin, size_t end) {
  std::fill(text.begin() + static_cast<std::ptrdiff_t>(begin), text.begin() + static_cast<std::ptrdiff_t>(end), ' ');
}

// Blender 3.4 reads a backslash at the end of an OBJ line (blanks may follow it) as the statement
// going on in the next line; tinyobjloader does not. The lines are joined into the first, and as
// many empty lines follow it as were joined, so that later line numbers stay the file's.
std::string with_continuations_joined(const std::string& text) {
  std::string joined;
  joined.reserve(text.size());
  size_t pending_lines = 0;
  for_each_line(text, [&](size_t begin, size_t end) {
    std::string_view line(text.data() + begin, end - begin);
    const size_t first = line.find_first_not_of(" \t"), last = line.find_last_not_of(" \t");
    // A comment ending in a backslash ("# exported from C:\models\") is a comment, not a join.
    const bool comment = pending_lines == 0 && first != std::string_view::npos && line[first] == '#';
    if (last != std::string_view::npos && line[last] == '\\' && !comment) {
      joined.append(line.substr(0, last)).push_back(' ');
      ++pending_lines;
      return;
    }
    joined.append(line).append(pending_lines + 1, '\n');
    pending_lines = 0;
  });
  joined.append(pending_lines, '\n');
  return joined;
}

}  // namespace

void screen_obj_text(const std::string& path, std::string& text) {
  text = with_continuations_joined(text);
  size_t line_number = 0;
  VertexCounts counts;
  for_each_line(text, [&](size_t begin, size_t end) {
    ++line_number;
    const std::string_view line = std::string_view(text.data() + begin, end - begin).substr(0, text.find('\0', begin) - begin);
    const std::string_view keyword = line_keyword(line);
    if (keyword == "v" || keyword == "vt" || keyword == "vn") {
      check_vertex_statement(path, line_number, keyword, line);
      ++(keyword == "v" ? counts.positions : keyword == "vt" ? counts.uvs : counts.normals);
    } else if (keyword == "f" || keyword == "l" || keyword == "p") {
      check_element_statement(path, line_number, keyword, line, counts);
      blank(text, begin + comment_start(line), end);
    } else if (keyword == "t" || keyword == "vw") {
      blank(text, begin, end);
    }
  });
}

size_t first_use_line(const std::string& text, std::string_view material) {
  size_t line_number = 0;
  size_t found = 0;
  for_each_line(text, [&](size_t begin, size_t end) {
    ++line_number;
    const std::string_view line(text.data() + begin, end - begin);
    if (found == 0 && line_keyword(line) == "usemtl" && statement_name(line) == material) found = line_number;
  });
  return found;
}

namespace {

// Blender 3.4's reading of "s" (obj_import_file_reader.cc): off for "0", for a word starting
// with "off" or "null", and for anything that does not start with an integer; any other
// integer, negative ones too, turns smoothing on. Group numbers make no sharp edges.
bool smoothing_on(std::string_view line) {
  const std::vector<std::string_view> words = statement_arguments(line);
  if (words.empty()) return false;
  const std::string_view word = words.front();
  if (word.rfind("off", 0) == 0 || word.rfind("null", 0) == 0) return false;
  long long value = 0;
  const char* start = word.data() + (word.front() == '+' ? 1 : 0);
  const auto [end, error] = std::from_chars(start, word.data() + word.size(), value);
  return error == std::errc() && end != start && value != 0;
}

}  // namespace

std::string tinyobj_text(const std::string& screened) {
  std::string out;
  out.reserve(screened.size());
  for_each_line(screened, [&](size_t begin, size_t end) {
    const std::string_view line(screened.data() + begin, end - begin);
    const std::string_view keyword = line_keyword(line);
    if (keyword == "usemtl") {
      out.append("usemtl ").append(name_word(statement_name(line)));
    } else if (keyword == "mtllib") {
      // One file name, the whole rest of the line, without a pair of quotes around it.
      std::string_view name = statement_name(line);
      if (name.size() >= 2 && name.front() == '"' && name.back() == '"') name = name.substr(1, name.size() - 2);
      out.append("mtllib ").append(name_word(name));
    } else if (keyword == "s") {
      out.append(smoothing_on(line) ? "s 1" : "s 0");
    } else if (keyword == "o") {
      // Blender starts every object flat.
      out.append(line).append("\ns 0");
    } else {
      out.append(line);
    }
    out.push_back('\n');
  });
  return out;
}

bool names_material_library(const std::string& text) {
  bool named = false;
  for_each_line(text, [&](size_t begin, size_t end) {
    named = named || line_keyword(std::string_view(text.data() + begin, end - begin)) == "mtllib";
  });
  return named;
}

}  // namespace matgeom::obj
