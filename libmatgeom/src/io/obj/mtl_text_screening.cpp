#include "io/obj/mtl_text_screening.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <initializer_list>
#include <iomanip>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <string_view>
#include <vector>

#include "matbase/file/file_error.h"
#include "matgeom/object_asset.h"
#include "matmaterial/material_parameters.h"
#include "io/obj/material_names.h"
#include "io/obj/statement_text.h"

namespace matgeom::obj {
namespace {

using P = matmaterial::MaterialParameter;

// The largest number tinyobjloader's float holds: the bound of numbers with no range of their own.
constexpr double kFloatMax = std::numeric_limits<float>::max();

// Ni as Blender 3.4 takes it: any IOR from 0 to the Principled BSDF's 1000. Exporters write
// "Ni 0" for "unset"; the MTL spec's range is 0.001 to 10. An IOR shades only glass, so
// mtl_materials.cpp holds it to the parameter's range only for a material that transmits.
constexpr double kMaxNi = 1000.0;

// What a statement of numbers takes: a colour (3 numbers, or 1 for a grey), one number or one
// whole number.
enum class Takes { Colour, Number, WholeNumber };

// A statement of numbers: its keyword, what it takes and the values it may take.
struct NumberStatement {
  std::string_view keyword;
  Takes takes;
  double min, max;
};

constexpr NumberStatement parameter_statement(std::string_view keyword, Takes takes, P p) {
  return {keyword, takes, matmaterial::material_parameter(p).min, matmaterial::material_parameter(p).max};
}

// What mtl_materials.cpp makes of each: Ka's mean is the metallic of a reflecting illum model (3 to
// 8) and nothing otherwise, so its range is checked there, where it is used; Ks's the specular, Tf's (Kt in
// some files) the transmission; Tr is 1 - d (Blender ignores it). A Ke above 1 is a brighter
// emission (its largest component becomes the strength). Ns has no upper bound: the MTL spec
// says its values "normally" lie in [0, 1000], and Blender reads a higher one as 1000, the
// tightest highlight. aniso and anisor (the PBR extension's anisotropy and its rotation, both
// fractions) shade nothing here.
constexpr std::array<NumberStatement, 18> kNumberStatements = {{
    {"Ka", Takes::Colour, 0.0, kFloatMax},
    parameter_statement("Kd", Takes::Colour, P::BaseColor),
    parameter_statement("Ks", Takes::Colour, P::Specular),
    parameter_statement("Kt", Takes::Colour, P::Transmission),
    parameter_statement("Tf", Takes::Colour, P::Transmission),
    {"Ke", Takes::Colour, 0.0, matmaterial::material_parameter(P::EmissionStrength).max},
    {"Ns", Takes::Number, 0.0, kFloatMax},
    {"Ni", Takes::Number, 0.0, kMaxNi},
    parameter_statement("d", Takes::Number, P::Alpha),
    parameter_statement("Tr", Takes::Number, P::Alpha),
    parameter_statement("Pr", Takes::Number, P::Roughness),
    parameter_statement("Pm", Takes::Number, P::Metallic),
    parameter_statement("Pc", Takes::Number, P::Clearcoat),
    parameter_statement("Pcr", Takes::Number, P::ClearcoatRoughness),
    parameter_statement("Ps", Takes::Number, P::Sheen),
    {"aniso", Takes::Number, 0.0, 1.0},
    {"anisor", Takes::Number, 0.0, 1.0},
    {"illum", Takes::WholeNumber, 0.0, 10.0},  // the illumination models 0 to 10
}};

// The texture statements tinyobjloader reads, with options before the file name.
constexpr std::array<std::string_view, 17> kMapStatements = {
    "map_Ka", "map_Kd", "map_Ks",  "map_Ns", "map_bump", "map_Bump", "bump",   "map_d", "map_disp",
    "map_Disp", "disp",  "refl",   "map_Pr", "map_Pm",   "map_Ps",   "map_Ke", "norm"};

// A range as a message states it: whole numbers in full ("1000000", not "1e+06").
std::string range_text(double min, double max) {
  const auto shown = [](double bound) {
    std::ostringstream out;
    out << std::setprecision(15) << bound;
    return out.str();
  };
  return "[" + shown(min) + ", " + (max == kFloatMax ? "...)" : shown(max) + "]");
}

// Reports problems at one line of one .mtl file.
class LineChecker {
 public:
  LineChecker(const std::string& obj_path, const std::string& mtl_path) : obj_path_(obj_path), mtl_path_(mtl_path) {}

  void at_line(size_t line) { line_ = line; }

  [[noreturn]] void fail_here(const std::string& problem) const {
    matbase::fail(obj_path_, matbase::concat(mtl_path_, ": line ", line_, ": ", problem));
  }

  // The one number parser of every MTL statement and option: `word` is a finite number within
  // [min, max], reported as written when it is not.
  double number(std::string_view what, std::string_view word, double min, double max) const {
    const std::optional<double> value = finite_number(word);
    if (!value) fail_here(matbase::concat(what, ": ", matbase::excerpt(word), " is not a finite number"));
    if (!(*value >= min && *value <= max))
      fail_here(matbase::concat(what, ": ", matbase::excerpt(word), " is outside ", range_text(min, max)));
    return *value;
  }

  int64_t whole_number(std::string_view what, std::string_view word, int64_t min, int64_t max) const {
    const std::optional<int64_t> value = integer_number(word);
    if (!value) fail_here(matbase::concat(what, ": ", matbase::excerpt(word), " is not a whole number"));
    if (*value < min || *value > max) fail_here(matbase::concat(what, ": ", matbase::excerpt(word), " is outside [", min, ", ", max, "]"));
    return *value;
  }

 private:
  const std::string& obj_path_;
  const std::string& mtl_path_;
  size_t line_ = 0;
};

// A number statement as tinyobjloader must read it: a colour of one number as three.
std::string checked_number_statement(const LineChecker& checker, const NumberStatement& statement,
                                     const std::vector<std::string_view>& numbers) {
  const size_t count = numbers.size();
  const bool colour = statement.takes == Takes::Colour;
  if (colour ? count != 1 && count != 3 : count != 1) {
    checker.fail_here(
        matbase::concat(statement.keyword, " takes ", colour ? "3 numbers (or 1 for a grey)" : "1 number", "; it has ", count));
  }
  for (const std::string_view word : numbers) {
    if (statement.takes == Takes::WholeNumber)
      checker.whole_number(statement.keyword, word, static_cast<int64_t>(statement.min),
                           static_cast<int64_t>(statement.max));
    else
      checker.number(statement.keyword, word, statement.min, statement.max);
  }
  std::string text(statement.keyword);
  for (size_t c = 0; c < (colour ? 3 : 1); ++c) text.append(" ").append(numbers[std::min(c, count - 1)]);
  return text;
}

// The words of a map statement from the front, options first and then the file name, which is
// the rest of the line (it may hold blanks).
class MapWords {
 public:
  explicit MapWords(std::string_view rest) : rest_(rest) {}

  bool empty() const { return rest_.empty(); }
  std::string_view rest() const { return rest_; }
  std::string_view peek() const { return rest_.substr(0, rest_.find_first_of(" \t")); }

  std::string_view take() {
    const std::string_view word = peek();
    const size_t next = rest_.find_first_not_of(" \t", word.size());
    rest_ = next == std::string_view::npos ? std::string_view() : rest_.substr(next);
    return word;
  }

 private:
  std::string_view rest_;
};

// An option's numbers: the word after it, whatever it is (the option needs one), and up to
// `most` - 1 more that are numbers (tinyobjloader's file name may follow them).
std::vector<std::string_view> take_numbers(MapWords& words, size_t most) {
  std::vector<std::string_view> numbers;
  if (!words.empty()) numbers.push_back(words.take());
  while (numbers.size() < most && !words.empty() && is_decimal_number(words.peek())) numbers.push_back(words.take());
  return numbers;
}

// -o u [v [w]], -s u [v [w]], -t u [v [w]]: texture offset, scale and turbulence. Blender ignores
// -t; -o and -s place the texture (mtl_placement.h), any finite numbers but a scale of 0 in u or v,
// which would shrink the whole image onto one line of texels.
std::string checked_placement(const LineChecker& checker, std::string_view where, std::string_view option,
                              MapWords& words) {
  const std::vector<std::string_view> numbers = take_numbers(words, 3);
  const std::string what = matbase::concat(where, " ", option);
  if (numbers.empty()) checker.fail_here(what + " needs 1 to 3 numbers");
  const std::string_view fill = option == "-s" ? "1" : "0";
  std::string text(option);
  for (size_t c = 0; c < 3; ++c) {
    const std::string_view number = c < numbers.size() ? numbers[c] : fill;
    const double value = checker.number(what, number, -kFloatMax, kFloatMax);
    if (option == "-s" && c < 2 && value == 0.0)
      checker.fail_here(matbase::concat(what, ": ", matbase::excerpt(number), " scales the texture to nothing (", c == 0 ? "u" : "v",
                               " must not be 0)"));
    text.append(" ").append(number);
  }
  return text;
}

// One of the words an option takes.
std::string_view checked_choice(const LineChecker& checker, const std::string& what, MapWords& words,
                                std::initializer_list<std::string_view> choices) {
  const std::string_view word = words.empty() ? std::string_view() : words.take();
  if (std::find(choices.begin(), choices.end(), word) == choices.end()) {
    std::string listed;
    for (const std::string_view choice : choices) listed += (listed.empty() ? "" : ", ") + std::string(choice);
    checker.fail_here(matbase::concat(what, " takes one of ", listed, "; not ", matbase::excerpt(word)));
  }
  return word;
}

// A texture statement as tinyobjloader must read it: "<keyword> <options> <file name>".
std::string checked_map_statement(const LineChecker& checker, std::string_view keyword, std::string_view rest) {
  MapWords words(rest);
  std::string text(keyword);
  while (!words.empty() && words.peek().size() > 1 && words.peek().front() == '-') {
    const std::string_view option = words.take();
    const std::string what = matbase::concat(keyword, " ", option);
    text.append(" ");
    if (option == "-o" || option == "-s" || option == "-t") {
      text += checked_placement(checker, keyword, option, words);
      continue;
    }
    text.append(option).append(" ");
    if (option == "-blendu" || option == "-blendv" || option == "-clamp") {
      text += checked_choice(checker, what, words, {"on", "off"});
    } else if (option == "-imfchan") {
      text += checked_choice(checker, what, words, {"r", "g", "b", "m", "l", "z"});
    } else if (option == "-type") {
      text += checked_choice(checker, what, words,
                             {"sphere", "cube_top", "cube_bottom", "cube_front", "cube_back", "cube_left", "cube_right"});
    } else if (option == "-bm" || option == "-boost") {
      // -bm is the normal map's strength (mtl_materials.cpp); -boost sharpens mip-maps, which
      // Blender ignores.
      const std::vector<std::string_view> number = take_numbers(words, 1);
      if (number.empty()) checker.fail_here(what + " needs a number");
      checker.number(what, number[0], option == "-bm" ? 0.0 : -kFloatMax, kFloatMax);
      text += number[0];
    } else if (option == "-mm") {
      // base and gain of the texture's values, which Blender ignores
      const std::vector<std::string_view> numbers = take_numbers(words, 2);
      if (numbers.empty()) checker.fail_here(what + " needs 1 or 2 numbers");
      for (const std::string_view number : numbers) checker.number(what, number, -kFloatMax, kFloatMax);
      text.append(numbers[0]);
      if (numbers.size() == 2) text.append(" ").append(numbers[1]);
    } else if (option == "-texres") {
      const std::string_view word = words.empty() ? std::string_view() : words.take();
      checker.whole_number(what, word, 1, std::numeric_limits<int>::max());
      text += word;
    } else if (option == "-colorspace") {
      if (words.empty()) checker.fail_here(what + " needs a colour space name");
      text += words.take();
    } else {
      checker.fail_here(matbase::concat(keyword, ": unknown option ", matbase::excerpt(option)));
    }
  }
  if (words.empty()) checker.fail_here(matbase::concat(keyword, ": no file name"));
  return text.append(" ").append(words.rest());
}

// tinyobjloader fills whatever a material leaves out with its own defaults (Ns 1, Ka 0, Pr 0...),
// indistinguishable from written values. Blender's MTL parser (io/wavefront_obj/importer/
// obj_import_file_reader.cc) marks them -1 instead, and its importer then picks defaults that
// depend on illum. Starting every material with these lines makes tinyobjloader report the same
// markers (a value the file gives comes later and replaces its marker).
// The d marker also keeps tinyobjloader from reading Tr as 1 - d: Blender 3.4 ignores Tr.
constexpr const char* kNotGivenMarkers =
    "Ns -1\nKa -1 -1 -1\nKd -1 -1 -1\nKs -1 -1 -1\nPr -1\nPm -1\nNi -1\nd -1\nKe -1 -1 -1\nTf -1 -1 -1\n"
    "Pc -1\nPcr -1\nPs -1\n";

// A line without trailing blanks, as tinyobjloader's LoadMtl trims it.
std::string_view trimmed_line(std::string_view line) {
  const size_t last = line.find_last_not_of(" \t");
  return line.substr(0, last == std::string_view::npos ? 0 : last + 1);
}

}  // namespace

std::string screened_mtl_text(const std::string& obj_path, const std::string& mtl_path, const std::string& text,
                              std::vector<std::string>& notes) {
  LineChecker checker(obj_path, mtl_path);
  std::map<std::string, size_t, std::less<>> material_lines;
  std::string screened;
  size_t line_number = 0;
  for_each_line(text, [&](size_t begin, size_t end) {
    checker.at_line(++line_number);
    const std::string_view line(text.data() + begin, end - begin);
    const std::string_view parsed = parsed_part(line);
    const std::vector<std::string_view> words = split_words(parsed);
    const std::string_view keyword = words.empty() ? std::string_view() : words.front();
    const auto number_statement = std::find_if(kNumberStatements.begin(), kNumberStatements.end(),
                                               [&](const NumberStatement& s) { return s.keyword == keyword; });
    if (number_statement != kNumberStatements.end()) {
      screened += checked_number_statement(checker, *number_statement, statement_arguments(parsed));
    } else if (std::find(kMapStatements.begin(), kMapStatements.end(), keyword) != kMapStatements.end()) {
      screened += checked_map_statement(checker, keyword, after_keyword(parsed));
    } else if (keyword == "newmtl") {
      const std::string_view name = statement_name(line);
      if (name.empty()) checker.fail_here("newmtl without a material name");
      // Blender uses the first definition of a name, as tinyobjloader's material map keeps it.
      const auto [first, inserted] = material_lines.emplace(std::string(name), line_number);
      if (!inserted)
        add_note(notes, matbase::concat(mtl_path, ": line ", line_number, ": material ", matbase::excerpt(name),
                                        " is defined again (first on line ", first->second, "); the first definition is used, as Blender uses it"));
      screened.append(line);
    } else {
      screened.append(line);
    }
    screened.push_back('\n');
  });
  return screened;
}

std::string with_not_given_markers(const std::string& text) {
  std::string marked = kNotGivenMarkers;
  for_each_line(text, [&](size_t begin, size_t end) {
    const std::string_view line(text.data() + begin, end - begin);
    const std::string_view trimmed = trimmed_line(line);
    if (line_keyword(trimmed) != "newmtl") {
      marked.append(line.data(), line.size()).push_back('\n');
      return;
    }
    // Blender trims material names and keeps their inner blanks (material_names.h).
    marked.append("newmtl ").append(name_word(statement_name(trimmed))).append("\n").append(kNotGivenMarkers);
  });
  return marked;
}

}  // namespace matgeom::obj
