#include "matbase/document/document_node.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>

#include "matbase/number_text.h"

namespace matbase {
namespace {

using Kind = DocumentValue::Kind;

// RFC 6901: "~" is written "~0" and "/" is written "~1" inside a pointer's token.
std::string pointer_token(const std::string& key) {
  std::string token;
  for (char c : key) {
    if (c == '~') token += "~0";
    else if (c == '/') token += "~1";
    else token += c;
  }
  return token;
}

// What a refusal says it found: the scalar as written (text in quotes), or the kind of value.
std::string found(const DocumentValue& value) {
  switch (value.kind) {
    case Kind::Null: return "null";
    case Kind::List: return "a list";
    case Kind::Mapping: return "a mapping of keys";
    case Kind::Text: return "\"" + shown_value(value.scalar) + "\"";
    case Kind::Boolean:
    case Kind::Number:
    case Kind::Bare: return shown_value(value.scalar);
  }
  return "";
}

// Integers read exactly up to here from a spelling with a fraction or an exponent ("3.0", "1e3").
constexpr double kLargestExactInteger = 9007199254740992.0;  // 2^53

// `spelling` as a whole number: digits, or a number whose fraction is zero.
template <class Integer>
std::optional<Integer> whole_value(const std::string& spelling) {
  if constexpr (std::is_signed_v<Integer>) {
    if (const std::optional<int64_t> exact = whole_number(spelling)) return exact;
  } else {
    if (const std::optional<uint64_t> exact = unsigned_whole_number(spelling)) return exact;
  }
  const std::optional<double> real = finite_number(spelling);
  if (!real || std::trunc(*real) != *real || std::abs(*real) > kLargestExactInteger) return std::nullopt;
  if (!std::is_signed_v<Integer> && *real < 0.0) return std::nullopt;
  return static_cast<Integer>(*real);
}

}  // namespace

std::string quoted_list(const std::vector<std::string>& names) {
  std::string list;
  for (const std::string& name : names) list += (list.empty() ? "\"" : ", \"") + name + "\"";
  return list;
}

std::string DocumentSource::place(const std::string& path) const {
  if (path.empty()) return name_;
  const char separator = style_ == PathStyle::JsonPointer ? '/' : '.';
  for (std::string around = path; !around.empty();) {
    if (const auto it = options_.find(around); it != options_.end()) return it->second + " (" + path + ")";
    const size_t last = around.rfind(separator);
    around.resize(last == std::string::npos ? 0 : last);
  }
  for (const auto& [overridden, option] : options_)
    if (overridden.rfind(path + separator, 0) == 0) return option + " (" + path + ")";
  return name_ + ": " + path;
}

std::string DocumentSource::child_path(const std::string& path, const std::string& key) const {
  if (style_ == PathStyle::JsonPointer) return path + "/" + pointer_token(key);
  return path.empty() ? key : path + "." + key;
}

std::string DocumentSource::item_path(const std::string& path, size_t index) const {
  return child_path(path, std::to_string(index));
}

void DocumentNode::fail(const std::string& problem) const { throw InputError(place() + ": " + problem); }

void DocumentNode::fail_expected(const std::string& expectation) const {
  fail("expected " + expectation + ", got " + found(value_));
}

bool DocumentNode::is_number() const { return number_spelling() && finite_number(value_.scalar); }

bool DocumentNode::is_text() const { return value_.kind == Kind::Text || value_.kind == Kind::Bare; }

void DocumentNode::expect_keys(std::initializer_list<const char*> allowed) const {
  expect_keys(std::vector<const char*>(allowed));
}

void DocumentNode::expect_keys(const std::vector<const char*>& allowed) const {
  if (!is_mapping()) fail_expected("a mapping of keys");
  for (size_t k = 0; k < value_.keys.size(); ++k) {
    const std::string& key = value_.keys[k];
    if (std::none_of(allowed.begin(), allowed.end(), [&](const char* name) { return key == name; }))
      member_node(k).fail("unknown key (allowed here: " +
                          quoted_list(std::vector<std::string>(allowed.begin(), allowed.end())) + ")");
  }
}

const DocumentValue* DocumentNode::member(const std::string& key) const {
  if (!is_mapping()) return nullptr;
  const auto it = std::find(value_.keys.begin(), value_.keys.end(), key);
  return it == value_.keys.end() ? nullptr : &value_.items[static_cast<size_t>(it - value_.keys.begin())];
}

DocumentNode DocumentNode::member_node(size_t index) const {
  return DocumentNode(value_.items[index], source_.child_path(path_, value_.keys[index]), source_);
}

bool DocumentNode::has(const std::string& key) const { return member(key) != nullptr; }

bool DocumentNode::is_null_at(const std::string& key) const {
  const DocumentValue* value = member(key);
  return value && value->kind == Kind::Null;
}

DocumentNode DocumentNode::required(const std::string& key) const {
  if (!is_mapping()) fail_expected("a mapping of keys");
  const std::optional<DocumentNode> node = find(key);
  if (!node) fail("missing key \"" + key + "\"");
  return *node;
}

std::optional<DocumentNode> DocumentNode::find(const std::string& key) const {
  const DocumentValue* value = member(key);
  if (!value) return std::nullopt;
  DocumentNode node(*value, source_.child_path(path_, key), source_);
  if (node.is_null()) node.fail("no value given: write one, or leave the key out for its default");
  return node;
}

std::vector<std::pair<std::string, DocumentNode>> DocumentNode::members() const {
  if (!is_mapping()) fail_expected("a mapping of keys");
  std::vector<std::pair<std::string, DocumentNode>> result;
  for (size_t k = 0; k < value_.keys.size(); ++k) result.emplace_back(value_.keys[k], member_node(k));
  return result;
}

std::vector<DocumentNode> DocumentNode::items(const std::string& expectation) const {
  if (!is_list()) fail_expected(expectation);
  std::vector<DocumentNode> result;
  for (size_t k = 0; k < value_.items.size(); ++k)
    result.push_back(DocumentNode(value_.items[k], source_.item_path(path_, k), source_));
  return result;
}

std::vector<DocumentNode> DocumentNode::items(size_t count, const std::string& expectation) const {
  if (!is_list() || value_.items.size() != count) fail_expected(expectation);
  return items(expectation);
}

std::string DocumentNode::text() const {
  if (!is_text()) fail_expected("a string");
  return value_.scalar;
}

bool DocumentNode::boolean() const {
  const bool spelled = value_.kind == Kind::Boolean || value_.kind == Kind::Bare;
  if (spelled && value_.scalar == "true") return true;
  if (spelled && value_.scalar == "false") return false;
  fail_expected("true or false");
}

size_t DocumentNode::choice(const std::vector<std::string>& choices) const {
  // A boolean matches the choice spelled as it is (denoise: false).
  const bool spelled = is_text() || value_.kind == Kind::Boolean;
  const auto it = spelled ? std::find(choices.begin(), choices.end(), value_.scalar) : choices.end();
  if (it == choices.end()) fail_expected("one of " + quoted_list(choices));
  return static_cast<size_t>(it - choices.begin());
}

const std::string* DocumentNode::number_spelling() const {
  const bool numeric = value_.kind == Kind::Number || value_.kind == Kind::Bare;
  return numeric ? &value_.scalar : nullptr;
}

double DocumentNode::number() const {
  return number_in(-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity());
}

double DocumentNode::number_in(double low, double high, bool low_open) const {
  const std::string* spelling = number_spelling();
  const std::optional<double> value = spelling ? finite_number(*spelling) : std::nullopt;
  if (value && (low_open ? *value > low : *value >= low) && *value <= high) return *value;
  fail_expected(number_expectation(low, high, low_open));
}

double DocumentNode::positive() const { return number_in(0.0, std::numeric_limits<double>::infinity(), true); }

double DocumentNode::non_negative() const { return number_in(0.0, std::numeric_limits<double>::infinity()); }

double DocumentNode::unit_interval() const { return number_in(0.0, 1.0); }

double DocumentNode::number_where(const std::function<bool(double)>& accept, const std::string& expectation) const {
  const std::string* spelling = number_spelling();
  const std::optional<double> value = spelling ? finite_number(*spelling) : std::nullopt;
  if (!value || !accept(*value)) fail_expected(expectation);
  return *value;
}

int64_t DocumentNode::whole_number(int64_t low, int64_t high) const {
  const std::string* spelling = number_spelling();
  const std::optional<int64_t> value = spelling ? whole_value<int64_t>(*spelling) : std::nullopt;
  if (!value || *value < low || *value > high) fail_expected(whole_number_expectation(low, high));
  return *value;
}

int DocumentNode::integer_in(int low, int high) const { return static_cast<int>(whole_number(low, high)); }

int DocumentNode::integer_at_least(int low) const {
  return integer_in(low, std::numeric_limits<int>::max());
}

uint32_t DocumentNode::uint32() const {
  return static_cast<uint32_t>(whole_number(0, std::numeric_limits<uint32_t>::max()));
}

uint64_t DocumentNode::seed() const {
  const std::string* spelling = number_spelling();
  const std::optional<uint64_t> value = spelling ? whole_value<uint64_t>(*spelling) : std::nullopt;
  if (!value) fail_expected(seed_expectation());
  return *value;
}

}  // namespace matbase
