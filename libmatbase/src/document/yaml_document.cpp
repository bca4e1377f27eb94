#include "matbase/document/yaml_document.h"

#include <fmt/format.h>

#include "matbase/document/document_node.h"
#include "matbase/input_error.h"

namespace matbase {
namespace {

using Kind = DocumentValue::Kind;

// "lines 3 and 7", or "line 1, columns 2 and 30" for JSON on one line.
std::string where_both(const YAML::Mark& first, const YAML::Mark& second) {
  if (first.line != second.line) return fmt::format("lines {} and {}", first.line + 1, second.line + 1);
  return fmt::format("line {}, columns {} and {}", first.line + 1, first.column + 1, second.column + 1);
}

// A scalar's type as YAML leaves it: quoted or tagged as a string, it is text; plain, it is the
// reader's to decide.
Kind scalar_kind(const YAML::Node& node) {
  const std::string& tag = node.Tag();
  return tag == "!" || tag == "tag:yaml.org,2002:str" ? Kind::Text : Kind::Bare;
}

class Converter {
 public:
  explicit Converter(const std::string& source) : source_(source, PathStyle::DottedKeys) {}

  DocumentValue value(const YAML::Node& node, const std::string& path, int depth) const {
    if (node.IsScalar()) return {scalar_kind(node), node.Scalar(), {}, {}};
    if (!node.IsSequence() && !node.IsMap()) return {};  // null
    // An alias inside the list or mapping it names ("&a [*a]") nests without end.
    if (depth >= kMaxDocumentDepth)
      fail(path, fmt::format("lists and mappings nest deeper than {} levels", kMaxDocumentDepth));
    DocumentValue result;
    if (node.IsSequence()) {
      result.kind = Kind::List;
      for (size_t k = 0; k < node.size(); ++k) result.items.push_back(value(node[k], source_.item_path(path, k), depth + 1));
      return result;
    }
    result.kind = Kind::Mapping;
    // yaml-cpp keeps every entry of a repeated key and its lookups return the first, where a
    // reader iterating the mapping would take the last: a repeated key is refused instead.
    std::vector<YAML::Mark> marks;
    for (const auto& entry : node) {
      if (!entry.first.IsScalar()) fail(path, "a key must be a single value, not a list or a mapping");
      const std::string& key = entry.first.Scalar();
      const std::string key_path = source_.child_path(path, key);
      for (size_t k = 0; k < result.keys.size(); ++k)
        if (result.keys[k] == key)
          fail(key_path, "given twice (" + where_both(marks[k], entry.first.Mark()) + "); say it once");
      result.keys.push_back(key);
      marks.push_back(entry.first.Mark());
      result.items.push_back(value(entry.second, key_path, depth + 1));
    }
    return result;
  }

 private:
  [[noreturn]] void fail(const std::string& path, const std::string& problem) const {
    throw InputError(source_.place(path) + ": " + problem);
  }

  DocumentSource source_;
};

}  // namespace

DocumentValue yaml_document_value(const YAML::Node& node, const std::string& source) {
  return Converter(source).value(node, "", 0);
}

}  // namespace matbase
