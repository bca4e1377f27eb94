#pragma once
// A parsed document (a scene file, make_dataset's configuration) as one tree, whatever it was
// written in: json_document.h builds it from JSON, yaml_document.h from YAML, and DocumentNode
// (document_node.h) reads it with checks. Scalars keep their spelling, so a number is read from
// what the user wrote and a refusal quotes it.
#include <string>
#include <vector>

namespace matbase {

struct DocumentValue {
  enum class Kind {
    Null,     // JSON null; YAML ~, null or nothing
    Boolean,  // JSON true or false
    Number,   // JSON number
    Text,     // JSON string; YAML quoted scalar
    // A YAML scalar written without quotes: YAML leaves its type to the reader, so it is a
    // number where a number is read and text where text is ("seed: 3", "name: 2024").
    Bare,
    List,
    Mapping,
  };

  Kind kind = Kind::Null;
  std::string scalar;                // a scalar's spelling: "0.5", "true", "wood/raw:1"
  std::vector<std::string> keys;     // a mapping's keys, in document order, each once
  std::vector<DocumentValue> items;  // a list's items; a mapping's values, keys[k] -> items[k]
};

// How deep lists and mappings may nest: far beyond any scene or configuration, and far below
// what would exhaust the stack of a reader that recurses.
constexpr int kMaxDocumentDepth = 256;

}  // namespace matbase
