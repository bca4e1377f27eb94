#pragma once
// OBJ and MTL lines split as tinyobjloader 2.0.0rc10 splits them, and the one checked number
// parser every statement's numbers go through: tinyobjloader reads any word that is not a number
// as 0 (or as its default) without a word, and an int index by atoi, which wraps.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace matgeom::obj {

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

// A line as tinyobjloader's C-string parsing sees it: up to a NUL byte, without trailing blanks.
inline std::string_view parsed_part(std::string_view line) {
  line = line.substr(0, line.find('\0'));
  const size_t last = line.find_last_not_of(" \t");
  return line.substr(0, last == std::string_view::npos ? 0 : last + 1);
}

// The keyword a line starts with as tinyobjloader tests keywords: after leading blanks and up to
// the next blank; empty when no blank follows it (tinyobjloader then ignores the line).
inline std::string_view line_keyword(std::string_view line) {
  const size_t begin = line.find_first_not_of(" \t");
  if (begin == std::string_view::npos) return {};
  const size_t end = line.find_first_of(" \t", begin);
  if (end == std::string_view::npos) return {};
  return line.substr(begin, end - begin);
}

// What follows a line's keyword, without leading blanks.
inline std::string_view after_keyword(std::string_view line) {
  const size_t keyword = line.find_first_not_of(" \t");
  const size_t blank = line.find_first_of(" \t", keyword);
  if (blank == std::string_view::npos) return {};
  const size_t rest = line.find_first_not_of(" \t", blank);
  return rest == std::string_view::npos ? std::string_view() : line.substr(rest);
}

// The blank-separated words of `text`.
inline std::vector<std::string_view> split_words(std::string_view text) {
  std::vector<std::string_view> words;
  size_t position = text.find_first_not_of(" \t");
  while (position != std::string_view::npos) {
    const size_t end = std::min(text.find_first_of(" \t", position), text.size());
    words.push_back(text.substr(position, end - position));
    position = text.find_first_not_of(" \t", end);
  }
  return words;
}

// The words after a line's keyword up to a comment (a word starting with '#').
inline std::vector<std::string_view> statement_arguments(std::string_view line) {
  std::vector<std::string_view> words = split_words(after_keyword(parsed_part(line)));
  for (size_t i = 0; i < words.size(); ++i) {
    if (words[i].front() == '#') words.resize(i);
  }
  return words;
}

// A decimal number as C's strtod reads it without "nan", "inf" or hex.
inline bool is_decimal_number(std::string_view word) {
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

// The value of a decimal number that tinyobjloader's float can hold; nullopt for any other word
// ("nan", "red", "0,5", "1e39"). std::from_chars is exact and ignores the C locale.
inline std::optional<double> finite_number(std::string_view word) {
  if (!is_decimal_number(word)) return std::nullopt;
  if (word.front() == '+') word.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (error != std::errc() || end != word.data() + word.size()) return std::nullopt;
  if (!(std::abs(value) <= std::numeric_limits<float>::max())) return std::nullopt;
  return value;
}

// An integer as written ("-3", "+12"); nullopt for any other word or one beyond 64 bits.
inline std::optional<int64_t> integer_number(std::string_view word) {
  if (!word.empty() && word.front() == '+') word.remove_prefix(1);
  if (word.empty() || word.front() == '+') return std::nullopt;
  int64_t value = 0;
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (error != std::errc() || end != word.data() + word.size()) return std::nullopt;
  return value;
}

}  // namespace matgeom::obj
