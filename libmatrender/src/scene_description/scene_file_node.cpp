#include "scene_description/scene_file_node.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace matrender {
namespace {

constexpr long long kMaxUint32 = std::numeric_limits<uint32_t>::max();
constexpr long long kMaxInt = std::numeric_limits<int>::max();

}  // namespace

std::string quoted_list(const std::vector<std::string>& names) {
  std::string list;
  for (const std::string& name : names) list += (list.empty() ? "\"" : ", \"") + name + "\"";
  return list;
}

std::string pointer_token(const std::string& key) {
  std::string token;
  for (char c : key) {
    if (c == '~') token += "~0";
    else if (c == '/') token += "~1";
    else token += c;
  }
  return token;
}

[[noreturn]] void SceneFileNode::fail(const std::string& message) const { throw origin().error("", message); }

void SceneFileNode::expect_keys(std::initializer_list<const char*> allowed) const {
  expect_keys(std::vector<const char*>(allowed));
}

void SceneFileNode::expect_keys(const std::vector<const char*>& allowed) const {
  if (!value_.is_object()) fail("expected an object");
  for (const auto& item : value_.items()) {
    const bool known = std::any_of(allowed.begin(), allowed.end(),
                                   [&](const char* key) { return item.key() == key; });
    if (!known) {
      std::vector<std::string> names(allowed.begin(), allowed.end());
      member_node(item.key()).fail("unknown key (allowed here: " + quoted_list(names) + ")");
    }
  }
}

bool SceneFileNode::has(const char* key) const { return value_.is_object() && value_.contains(key); }

SceneFileNode SceneFileNode::required(const char* key) const {
  if (!value_.is_object()) fail("expected an object");
  if (!has(key)) fail(fmt::format("missing key \"{}\"", key));
  return member_node(key);
}

std::optional<SceneFileNode> SceneFileNode::find(const char* key) const {
  if (!has(key)) return std::nullopt;
  return member_node(key);
}

SceneFileNode SceneFileNode::item(size_t index) const {
  return SceneFileNode(value_.at(index), pointer_ + "/" + std::to_string(index), file_);
}

std::vector<std::pair<std::string, SceneFileNode>> SceneFileNode::members() const {
  if (!value_.is_object()) fail("expected an object");
  std::vector<std::pair<std::string, SceneFileNode>> result;
  for (const auto& item : value_.items()) result.emplace_back(item.key(), member_node(item.key()));
  return result;
}

bool SceneFileNode::is_array() const { return value_.is_array(); }

bool SceneFileNode::is_object() const { return value_.is_object(); }

bool SceneFileNode::is_string() const { return value_.is_string(); }

bool SceneFileNode::is_number() const { return value_.is_number(); }

size_t SceneFileNode::array_size(const std::string& expectation) const {
  if (!value_.is_array()) fail("expected " + expectation);
  return value_.size();
}

void SceneFileNode::expect_array(size_t count, const std::string& expectation) const {
  if (array_size(expectation) != count) fail("expected " + expectation);
}

double SceneFileNode::number() const {
  if (!value_.is_number()) fail("expected a number");
  return value_.get<double>();
}

double SceneFileNode::number_where(const std::function<bool(double)>& accept, const std::string& expectation) const {
  if (!value_.is_number() || !accept(value_.get<double>())) fail("expected " + expectation);
  return value_.get<double>();
}

double SceneFileNode::positive() const {
  return number_where([](double v) { return v > 0.0; }, "a positive number");
}

double SceneFileNode::non_negative() const {
  return number_where([](double v) { return v >= 0.0; }, "a number >= 0");
}

double SceneFileNode::unit_interval() const {
  return number_where([](double v) { return v >= 0.0 && v <= 1.0; }, "a number in [0, 1]");
}

int SceneFileNode::integer_in(int lo, int hi) const {
  return static_cast<int>(checked_integer(lo, hi, fmt::format("an integer in [{}, {}]", lo, hi)));
}

int SceneFileNode::integer_at_least(int lo) const {
  return static_cast<int>(checked_integer(lo, kMaxInt, fmt::format("an integer in [{}, {}]", lo, kMaxInt)));
}

uint32_t SceneFileNode::uint32() const {
  return static_cast<uint32_t>(checked_integer(0, kMaxUint32, "an integer in [0, 4294967295]"));
}

std::string SceneFileNode::string() const {
  if (!value_.is_string()) fail("expected a string");
  return value_.get<std::string>();
}

bool SceneFileNode::boolean() const {
  if (!value_.is_boolean()) fail("expected true or false");
  return value_.get<bool>();
}

size_t SceneFileNode::choice(const std::vector<std::string>& choices) const {
  const auto it = value_.is_string() ? std::find(choices.begin(), choices.end(), value_.get<std::string>())
                                     : choices.end();
  if (it == choices.end()) fail("expected one of " + quoted_list(choices));
  return static_cast<size_t>(it - choices.begin());
}

long long SceneFileNode::checked_integer(long long lo, long long hi, const std::string& expectation) const {
  const bool integral = value_.is_number_integer() ||
                        (value_.is_number_float() && std::trunc(value_.get<double>()) == value_.get<double>());
  const double v = integral ? value_.get<double>() : 0.0;
  if (!integral || v < static_cast<double>(lo) || v > static_cast<double>(hi)) fail("expected " + expectation);
  return static_cast<long long>(v);
}

SceneFileNode SceneFileNode::member_node(const std::string& key) const {
  return SceneFileNode(value_.at(key), pointer_ + "/" + pointer_token(key), file_);
}

glm::dvec3 read_vec3(const SceneFileNode& node) {
  node.expect_array(3, "an array of 3 numbers");
  return {node.item(0).number(), node.item(1).number(), node.item(2).number()};
}

glm::dvec3 read_color(const SceneFileNode& node) {
  node.expect_array(3, "[r, g, b] with components >= 0");
  return {node.item(0).non_negative(), node.item(1).non_negative(), node.item(2).non_negative()};
}

glm::dvec3 read_direction(const SceneFileNode& node) {
  const glm::dvec3 v = read_vec3(node);
  if (glm::length(v) == 0.0) node.fail("expected a non-zero vector");
  return v;
}

glm::dvec3 read_target(const SceneFileNode& node, const glm::dvec3& position) {
  const glm::dvec3 target = read_vec3(node.required("look_at"));
  if (target == position) node.required("look_at").fail("expected a point different from \"position\"");
  return target;
}

}  // namespace matrender
