#pragma once
// A value of a scene file (docs/scene_format.md) together with its file and JSON pointer, so that
// every check can name the value it rejects ("scene.json: /lights/2/power: expected a number >=
// 0"). The scene file's reader and each light's own reader (lights/light_kind.h) read through it.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json_fwd.hpp>

#include "matrender/scene_description.h"

namespace matrender {

class SceneFileNode {
 public:
  SceneFileNode(const nlohmann::json& value, std::string pointer, const std::string& file)
      : value_(value), pointer_(std::move(pointer)), file_(file) {}

  Origin origin() const { return {file_, pointer_}; }
  [[noreturn]] void fail(const std::string& message) const;

  // This must be an object whose keys are all in `allowed`: a misspelt key is an error rather
  // than a silently ignored setting.
  void expect_keys(std::initializer_list<const char*> allowed) const;
  void expect_keys(const std::vector<const char*>& allowed) const;

  bool has(const char* key) const;
  SceneFileNode required(const char* key) const;
  std::optional<SceneFileNode> find(const char* key) const;
  SceneFileNode item(size_t index) const;
  // Members of an object, in file order.
  std::vector<std::pair<std::string, SceneFileNode>> members() const;

  bool is_array() const;
  bool is_object() const;
  bool is_string() const;
  bool is_number() const;
  size_t array_size(const std::string& expectation) const;
  void expect_array(size_t count, const std::string& expectation) const;

  double number() const;
  double number_where(const std::function<bool(double)>& accept, const std::string& expectation) const;
  double positive() const;
  double non_negative() const;
  double unit_interval() const;
  int integer_in(int lo, int hi) const;
  int integer_at_least(int lo) const;
  uint32_t uint32() const;
  std::string string() const;
  bool boolean() const;
  // Index of the string among `choices`.
  size_t choice(const std::vector<std::string>& choices) const;

 private:
  // 3 and 3.0 are the same number to JSON writers, so both count as integers.
  long long checked_integer(long long lo, long long hi, const std::string& expectation) const;
  SceneFileNode member_node(const std::string& key) const;

  const nlohmann::json& value_;
  std::string pointer_;
  const std::string& file_;
};

// The small values every part of a scene file uses.
glm::dvec3 read_vec3(const SceneFileNode& node);
glm::dvec3 read_color(const SceneFileNode& node);  // [r, g, b], each >= 0
glm::dvec3 read_direction(const SceneFileNode& node);  // non-zero
// The node's "look_at", which must differ from `position`.
glm::dvec3 read_target(const SceneFileNode& node, const glm::dvec3& position);

// "\"a\", \"b\"": names as an error lists them.
std::string quoted_list(const std::vector<std::string>& names);
// RFC 6901: "~" is written "~0" and "/" is written "~1" inside a pointer token.
std::string pointer_token(const std::string& key);

}  // namespace matrender
