#pragma once
// Checks of a parsed YAML (or JSON) document that yaml-cpp does not make. It keeps every entry of
// a mapping that names a key twice, and its lookups return the first: make_dataset would use the
// first value and a reader iterating the map the last, so a repeated key is refused instead.
#include <optional>
#include <string>

#include <yaml-cpp/yaml.h>

namespace matbase {

// The first key named twice in one mapping of `document`, as "render.samples: given twice (lines
// 3 and 7); say it once", with the dotted path from the top; nothing when every key is named once.
std::optional<std::string> repeated_key_problem(const YAML::Node& document);

}  // namespace matbase
