#pragma once
// Numbers given on the command line (or in a settings file), checked against the range an option
// accepts, with refusals that state the range as a sentence. CLI11's own checks print their
// bounds in full (CLI::PositiveNumber's upper bound is DBL_MAX written out, 309 digits), and a
// value its conversion cannot hold only reads "Could not convert".
#include <cstdint>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "matbase/number_text.h"
#include "matbase/threads.h"

namespace app_support {

// Limits the tools share. More threads than a machine has are capped to it anyway; a batch of
// more samples than this is no training setting but a typo (4096 at 224 px is 2.3 GiB of input).
using matbase::kMaxThreadRequest;
constexpr int kMaxBatchSize = 4096;

// CLI11 validators of matbase/number_text.h's checks; their description, shown in --help, is
// the range ("1..65536").
CLI::Validator whole_number_in(int64_t low, int64_t high);
CLI::Validator any_seed();
// A finite number in [low, high], or (low, high] when low_open.
CLI::Validator number_in(double low, double high, bool low_open);

}  // namespace app_support
