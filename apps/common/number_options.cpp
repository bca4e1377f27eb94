#include "common/number_options.h"

#include <fmt/format.h>

#include "matbase/number_text.h"

namespace app_support {
namespace {

CLI::Validator validator(std::function<std::optional<std::string>(const std::string&)> problem,
                         const std::string& description) {
  return CLI::Validator(
      [problem](std::string& text) {
        const std::optional<std::string> found = problem(text);
        return found ? *found : std::string();
      },
      description);
}

}  // namespace

CLI::Validator whole_number_in(int64_t low, int64_t high) {
  return validator([low, high](const std::string& text) { return matbase::whole_number_problem(text, low, high); },
                   fmt::format("{}..{}", low, high));
}

CLI::Validator number_in(double low, double high, bool low_open) {
  return validator(
      [low, high, low_open](const std::string& text) { return matbase::number_problem(text, low, high, low_open); },
      fmt::format("{}{}..{}]", low_open ? "(" : "[", low, high));
}

CLI::Validator any_seed() { return validator(matbase::seed_problem, "0..2^64-1"); }

}  // namespace app_support
