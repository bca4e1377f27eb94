#include "matbase/document/yaml_checks.h"

#include <map>

#include <fmt/format.h>

namespace matbase {
namespace {

// "lines 3 and 7", or "line 1, columns 2 and 30" for JSON on one line.
std::string where_both(const YAML::Mark& first, const YAML::Mark& second) {
  if (first.line != second.line) return fmt::format("lines {} and {}", first.line + 1, second.line + 1);
  return fmt::format("line {}, columns {} and {}", first.line + 1, first.column + 1, second.column + 1);
}

std::optional<std::string> repeated_key_below(const YAML::Node& node, const std::string& path) {
  const auto child_path = [&](const std::string& name) { return path.empty() ? name : path + "." + name; };
  if (node.IsSequence()) {
    for (size_t k = 0; k < node.size(); ++k)
      if (auto problem = repeated_key_below(node[k], child_path(std::to_string(k)))) return problem;
  } else if (node.IsMap()) {
    std::map<std::string, YAML::Mark> first_seen;
    for (const auto& entry : node) {
      const std::string name = entry.first.IsScalar() ? entry.first.Scalar() : "(a key that is not a single value)";
      const YAML::Mark at = entry.first.Mark();
      if (const auto [it, inserted] = first_seen.emplace(name, at); !inserted)
        return fmt::format("{}: given twice ({}); say it once", child_path(name), where_both(it->second, at));
      if (auto problem = repeated_key_below(entry.second, child_path(name))) return problem;
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> repeated_key_problem(const YAML::Node& document) {
  return repeated_key_below(document, "");
}

}  // namespace matbase
