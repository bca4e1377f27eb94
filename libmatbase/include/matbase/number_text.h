#pragma once
// Numbers given as text (an option, a configuration value), read whole and checked against a
// range, with refusals that state the range as a sentence: "expected a whole number from 1 to
// 65,536, got 99999999999". Every tool's numeric options and every configuration reader use them.
#include <cstdint>
#include <optional>
#include <string>

namespace matbase {

// The whole of `text` as a number (decimal, C locale), or nothing: no sign where the type has
// none, no fraction in a whole number, nothing beyond the type's range, no trailing characters,
// and for a real number nothing infinite or NaN.
std::optional<int64_t> whole_number(const std::string& text);
std::optional<uint64_t> unsigned_whole_number(const std::string& text);
std::optional<double> finite_number(const std::string& text);

// What is wrong with `text` as a whole number in [low, high], or nothing when it is one:
// "expected a whole number from 1 to 65,536, got 99999999999".
std::optional<std::string> whole_number_problem(const std::string& text, int64_t low, int64_t high);
// The same for the full unsigned 64-bit range of seeds, [0, 18,446,744,073,709,551,615].
std::optional<std::string> seed_problem(const std::string& text);
// What is wrong with `text` as a finite number in [low, high] (or (low, high] when low_open; an
// infinite bound is none): "expected a number from 0 to 1, got 2", "... greater than 0, got 0",
// "... of at least 0, got -1".
std::optional<std::string> number_problem(const std::string& text, double low, double high, bool low_open);

// What the problems above expect, as their refusals word it: "a whole number from 1 to 65,536",
// "a whole number from 0 to 18,446,744,073,709,551,615", "a number greater than 0".
std::string whole_number_expectation(int64_t low, int64_t high);
std::string seed_expectation();
std::string number_expectation(double low, double high, bool low_open);

// A value as a refusal quotes it after "got": "nothing" for empty text, a long one cut.
std::string shown_value(const std::string& text);

// 1234567 -> "1,234,567".
std::string with_thousands(int64_t n);

}  // namespace matbase
