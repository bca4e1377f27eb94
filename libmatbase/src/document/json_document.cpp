#include "matbase/document/json_document.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <optional>
#include <utility>

#include <nlohmann/json.hpp>

#include "matbase/document/document_node.h"
#include "matbase/file/input_file.h"
#include "matbase/input_error.h"

namespace matbase {
namespace {

using Kind = DocumentValue::Kind;

// nlohmann's SAX events, each value appended to the list or mapping open around it. The events
// give a number's spelling as written, which the tree keeps.
class TreeBuilder : public nlohmann::json::json_sax_t {
 public:
  explicit TreeBuilder(const std::string& source) : source_(source, PathStyle::JsonPointer) {}

  DocumentValue take_root() { return std::move(*root_); }

  bool null() override { return add({Kind::Null, "null", {}, {}}); }
  bool boolean(bool value) override { return add({Kind::Boolean, value ? "true" : "false", {}, {}}); }
  bool number_integer(number_integer_t value) override { return add({Kind::Number, std::to_string(value), {}, {}}); }
  bool number_unsigned(number_unsigned_t value) override { return add({Kind::Number, std::to_string(value), {}, {}}); }
  bool number_float(number_float_t, const string_t& spelling) override { return add({Kind::Number, spelling, {}, {}}); }
  bool string(string_t& value) override { return add({Kind::Text, value, {}, {}}); }
  bool binary(binary_t&) override { return true; }  // JSON text has none

  bool start_object(std::size_t) override { return open(Kind::Mapping); }
  bool start_array(std::size_t) override { return open(Kind::List); }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }

  bool key(string_t& key) override {
    Open& mapping = open_.back();
    if (std::find(mapping.value.keys.begin(), mapping.value.keys.end(), key) != mapping.value.keys.end())
      throw InputError(source_.name() + ": " + source_.child_path(path_to_open(), key) + ": given twice; say it once");
    mapping.key = key;
    return true;
  }

  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& error) override {
    const std::string what = error.what();
    // A number beyond a double ("1e309"): nlohmann says "number overflow parsing '1e309'". The
    // JSON is valid (JSON sets no range), so the value is named by its pointer, as every other.
    if (error.id == 406) {
      const size_t quote = what.find('\'');
      throw InputError(source_.name() + ": " + path_of_next_value() + ": the number " +
                       (quote == std::string::npos ? std::string() : what.substr(quote) + " ") +
                       "is too large for a double");
    }
    // Drop nlohmann's "[json.exception.parse_error.101] " prefix; the rest names line and column.
    const size_t end_of_tag = what.find("] ");
    throw InputError(source_.name() + ": not valid JSON: " +
                     (end_of_tag == std::string::npos ? what : what.substr(end_of_tag + 2)));
  }

 private:
  struct Open {
    DocumentValue value;
    std::string key;  // a mapping's member being read
  };

  // The JSON pointer of the innermost open list or mapping.
  std::string path_to_open() const {
    std::string path;
    for (size_t k = 0; k + 1 < open_.size(); ++k)
      path = open_[k].value.kind == Kind::List ? source_.item_path(path, open_[k].value.items.size())
                                                : source_.child_path(path, open_[k].key);
    return path;
  }

  // The JSON pointer the value being read would have: the next item of the open list, the member
  // of the open mapping whose key was read, or the root ("").
  std::string path_of_next_value() const {
    if (open_.empty()) return "";
    const Open& innermost = open_.back();
    return innermost.value.kind == Kind::List ? source_.item_path(path_to_open(), innermost.value.items.size())
                                              : source_.child_path(path_to_open(), innermost.key);
  }

  bool open(Kind kind) {
    if (open_.size() >= static_cast<size_t>(kMaxDocumentDepth))
      throw InputError(source_.name() + ": lists and mappings nest deeper than " +
                       std::to_string(kMaxDocumentDepth) + " levels");
    open_.push_back({DocumentValue{kind, "", {}, {}}, ""});
    return true;
  }

  bool close() {
    DocumentValue value = std::move(open_.back().value);
    open_.pop_back();
    return add(std::move(value));
  }

  bool add(DocumentValue value) {
    if (open_.empty()) {
      root_ = std::move(value);
      return true;
    }
    DocumentValue& container = open_.back().value;
    if (container.kind == Kind::Mapping) container.keys.push_back(open_.back().key);
    container.items.push_back(std::move(value));
    return true;
  }

  DocumentSource source_;
  std::vector<Open> open_;
  std::optional<DocumentValue> root_;
};

}  // namespace

DocumentValue parse_json_document(std::istream& text, const std::string& source) {
  TreeBuilder builder(source);
  nlohmann::json::sax_parse(text, &builder);
  return builder.take_root();
}

DocumentValue read_json_document(const std::string& path) {
  if (const std::optional<std::string> problem = input_file_problem(path)) throw InputError(path + ": " + *problem);
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open: " + std::strerror(errno));
  return parse_json_document(in, path);
}

}  // namespace matbase
