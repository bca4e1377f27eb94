#include "matbase/number_text.h"

#include <charconv>
#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace matbase {
namespace {

// The whole of `text` as a T, or nothing (a sign where T has none, a fraction in an integer,
// digits beyond T's range, trailing characters).
template <class T>
std::optional<T> parse_all(const std::string& text) {
  T value{};
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (error != std::errc() || stop != end || text.empty()) return std::nullopt;
  return value;
}

// The value as the refusal quotes it: nothing is named, a very long one cut.
std::string shown(const std::string& text) {
  if (text.empty()) return "nothing";
  return text.size() > 40 ? text.substr(0, 37) + "..." : text;
}

std::string with_thousands_unsigned(uint64_t n) {
  std::string digits = std::to_string(n);
  for (int i = static_cast<int>(digits.size()) - 3; i > 0; i -= 3) digits.insert(static_cast<size_t>(i), ",");
  return digits;
}

}  // namespace

std::string with_thousands(int64_t n) {
  return n < 0 ? "-" + with_thousands_unsigned(static_cast<uint64_t>(-(n + 1)) + 1)
               : with_thousands_unsigned(static_cast<uint64_t>(n));
}

std::optional<int64_t> whole_number(const std::string& text) { return parse_all<int64_t>(text); }
std::optional<uint64_t> unsigned_whole_number(const std::string& text) { return parse_all<uint64_t>(text); }

std::optional<double> finite_number(const std::string& text) {
  const std::optional<double> value = parse_all<double>(text);
  return value && std::isfinite(*value) ? value : std::nullopt;
}

std::optional<std::string> whole_number_problem(const std::string& text, int64_t low, int64_t high) {
  const std::optional<int64_t> value = whole_number(text);
  if (value && *value >= low && *value <= high) return std::nullopt;
  return "expected a whole number from " + with_thousands(low) + " to " + with_thousands(high) + ", got " +
         shown(text);
}

std::optional<std::string> seed_problem(const std::string& text) {
  if (unsigned_whole_number(text)) return std::nullopt;
  return "expected a whole number from 0 to " + with_thousands_unsigned(std::numeric_limits<uint64_t>::max()) +
         ", got " + shown(text);
}

std::optional<std::string> number_problem(const std::string& text, double low, double high, bool low_open) {
  const std::optional<double> value = finite_number(text);
  if (value && (low_open ? *value > low : *value >= low) && *value <= high) return std::nullopt;
  const std::string range = low_open ? fmt::format("greater than {:g} and at most {:g}", low, high)
                                     : fmt::format("from {:g} to {:g}", low, high);
  return "expected a number " + range + ", got " + shown(text);
}

}  // namespace matbase
