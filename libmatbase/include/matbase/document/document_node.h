#pragma once
// One value of a document (document_value.h) with its place, whose getters check what they read
// and refuse it in one form: "<where>: <problem>", where <where> is the file and the value's path
// ("scene.json: /lights/2/power", "config.yaml: render.samples") or the command-line option that
// set it ("--spp (render.samples)"), and <problem> says what was expected and what was found
// ("expected a number of at least 0, got -1"). The scene file and make_dataset's configuration
// read through it.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "matbase/document/document_value.h"
#include "matbase/input_error.h"

namespace matbase {

// How a document names a value's path: a JSON pointer (RFC 6901: "/lights/2/power"), as the
// scene file's docs do, or dotted keys ("render.samples"), as make_dataset's --set does.
enum class PathStyle { JsonPointer, DottedKeys };

// Where a document's values come from: its file, or the options that overrode some of its paths.
class DocumentSource {
 public:
  DocumentSource(std::string name, PathStyle style) : name_(std::move(name)), style_(style) {}

  // The option `option` set the value at `path`.
  void overridden(const std::string& path, const std::string& option) { options_[path] = option; }
  bool is_overridden(const std::string& path) const { return options_.count(path) > 0; }

  // "config.yaml: render.samples"; "--spp (render.samples)" where an option set the path or a
  // path around it, else where it set a path inside it (`--set render.resolution.1=64` on a file
  // whose resolution is one side makes `render.resolution` wrong); the name alone at the root.
  std::string place(const std::string& path) const;
  std::string child_path(const std::string& path, const std::string& key) const;
  std::string item_path(const std::string& path, size_t index) const;

  const std::string& name() const { return name_; }
  PathStyle style() const { return style_; }

 private:
  std::string name_;
  PathStyle style_;
  std::map<std::string, std::string> options_;
};

class DocumentNode {
 public:
  // The root of a document. Both must outlive every node read from it.
  DocumentNode(const DocumentValue& root, const DocumentSource& source) : DocumentNode(root, "", source) {}

  const std::string& path() const { return path_; }
  const DocumentSource& source() const { return source_; }
  std::string place() const { return source_.place(path_); }
  [[noreturn]] void fail(const std::string& problem) const;
  // "expected <expectation>, got <what the value is>".
  [[noreturn]] void fail_expected(const std::string& expectation) const;

  bool is_null() const { return value_.kind == DocumentValue::Kind::Null; }
  bool is_list() const { return value_.kind == DocumentValue::Kind::List; }
  bool is_mapping() const { return value_.kind == DocumentValue::Kind::Mapping; }
  bool is_number() const;  // a JSON number, or a bare YAML scalar spelled as a finite number
  bool is_text() const;    // a JSON string, or any YAML scalar but null
  // Whether this is the text `word` ("auto", "centroid").
  bool is_word(const std::string& word) const { return is_text() && value_.scalar == word; }

  // Mappings. A key given with no value (null) is refused where it is read, rather than taken as
  // absent, which would silently give it its default; has() and is_null_at() see it.
  void expect_keys(std::initializer_list<const char*> allowed) const;  // a misspelt key is an error
  void expect_keys(const std::vector<const char*>& allowed) const;
  bool has(const std::string& key) const;
  bool is_null_at(const std::string& key) const;
  DocumentNode required(const std::string& key) const;
  std::optional<DocumentNode> find(const std::string& key) const;
  std::vector<std::pair<std::string, DocumentNode>> members() const;  // in document order

  // Lists; `expectation` describes the list in the refusal ("[r, g, b] with components >= 0").
  std::vector<DocumentNode> items(const std::string& expectation = "a list") const;
  std::vector<DocumentNode> items(size_t count, const std::string& expectation) const;

  // Scalars.
  std::string text() const;
  bool boolean() const;
  size_t choice(const std::vector<std::string>& choices) const;  // the index of the text (or a boolean spelled as a choice) among them
  double number() const;                                          // any finite number
  // A number in [low, high], or (low, high] when low_open; an infinite bound is no bound.
  double number_in(double low, double high, bool low_open = false) const;
  double positive() const;
  double non_negative() const;
  double unit_interval() const;
  // A finite number that `accept` takes; else "expected <expectation>, got ...".
  double number_where(const std::function<bool(double)>& accept, const std::string& expectation) const;
  // A number with no fraction in [low, high]: 3 and 3.0 are the same number to JSON's writers.
  int64_t whole_number(int64_t low, int64_t high) const;
  int integer_in(int low, int high) const;
  int integer_at_least(int low) const;
  uint32_t uint32() const;
  uint64_t seed() const;  // any whole number of 64 bits

 private:
  DocumentNode(const DocumentValue& value, std::string path, const DocumentSource& source)
      : value_(value), path_(std::move(path)), source_(source) {}
  const DocumentValue* member(const std::string& key) const;
  DocumentNode member_node(size_t index) const;
  // The scalar a number is read from: a JSON number's or a bare YAML scalar's spelling.
  const std::string* number_spelling() const;

  const DocumentValue& value_;
  std::string path_;
  const DocumentSource& source_;
};

// "\"a\", \"b\"": names as a refusal lists them.
std::string quoted_list(const std::vector<std::string>& names);

}  // namespace matbase
