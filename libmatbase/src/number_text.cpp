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

std::string with_thousands_unsigned(uint64_t n) {
  std::string digits = std::to_string(n);
  for (int i = static_cast<int>(digits.size()) - 3; i > 0; i -= 3) digits.insert(static_cast<size_t>(i), ",");
  return digits;
}

}  // namespace

std::string shown_value(const std::string& text) {
  if (text.empty()) return "nothing";
  return text.size() > 40 ? text.substr(0, 37) + "..." : text;
}

std::string with_thousands(int64_t n) {
  return n < 0 ? "-" + with_thousands_unsigned(static_cast<uint64_t>(-(n + 1)) + 1)
               : with_thousands_unsigned(static_cast<uint64_t>(n));
}

std::string whole_number_expectation(int64_t low, int64_t high) {
  return "a whole number from " + with_thousands(low) + " to " + with_thousands(high);
}

std::string seed_expectation() {
  return "a whole number from 0 to " + with_thousands_unsigned(std::numeric_limits<uint64_t>::max());
}

std::string number_expectation(double low, double high, bool low_open) {
  const bool below = std::isfinite(low), above = std::isfinite(high);
  if (below && above)
    return low_open ? fmt::format("a number greater than {:g} and at most {:g}", low, high)
                    : fmt::format("a number from {:g} to {:g}", low, high);
  if (below) return low_open ? fmt::format("a number greater than {:g}", low) : fmt::format("a number of at least {:g}", low);
  if (above) return fmt::format("a number of at most {:g}", high);
  return "a number";
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
  return "expected " + whole_number_expectation(low, high) + ", got " + shown_value(text);
}

std::optional<std::string> seed_problem(const std::string& text) {
  if (unsigned_whole_number(text)) return std::nullopt;
  return "expected " + seed_expectation() + ", got " + shown_value(text);
}

std::optional<std::string> number_problem(const std::string& text, double low, double high, bool low_open) {
  const std::optional<double> value = finite_number(text);
  if (value && (low_open ? *value > low : *value >= low) && *value <= high) return std::nullopt;
  return "expected " + number_expectation(low, high, low_open) + ", got " + shown_value(text);
}

}  // namespace matbase
