#pragma once
// A document yaml-cpp has parsed (YAML, or JSON, which YAML reads too) as a DocumentValue. A
// quoted scalar is text and an unquoted one Bare (its type is the reader's to decide, as YAML's
// core schema resolves it by its spelling); a key given twice is refused (repeated_key_problem).
#include <string>

#include <yaml-cpp/yaml.h>

#include "matbase/document/document_value.h"

namespace matbase {

// Throws matbase::InputError beginning "<source>: ".
DocumentValue yaml_document_value(const YAML::Node& node, const std::string& source);

}  // namespace matbase
