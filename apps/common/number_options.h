#pragma once
// Numbers given on the command line (or in a settings file), checked against the range an option
// accepts, with refusals that state the range as a sentence. CLI11's own checks print their
// bounds in full (CLI::PositiveNumber's upper bound is DBL_MAX written out, 309 digits), and a
// value its conversion cannot hold only reads "Could not convert".
#include <cstdint>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

namespace app_support {

// Limits the tools share. More threads than a machine has are capped to it anyway; a batch of
// more samples than this is no training setting but a typo (4096 at 224 px is 2.3 GiB of input).
constexpr int kMaxThreadRequest = 65536;
constexpr int kMaxBatchSize = 4096;

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
// What is wrong with `text` as a finite number in [low, high] (or (low, high] when low_open).
std::optional<std::string> number_problem(const std::string& text, double low, double high, bool low_open);

// CLI11 validators of the above; their description, shown in --help, is the range ("1..65536").
CLI::Validator whole_number_in(int64_t low, int64_t high);
CLI::Validator any_seed();

// 1234567 -> "1,234,567".
std::string with_thousands(int64_t n);

}  // namespace app_support
