#include "scene_description/scene_file_values.h"

#include <vector>

namespace matrender {

using matbase::DocumentNode;

glm::dvec3 read_vec3(const DocumentNode& node) {
  const std::vector<DocumentNode> xyz = node.items(3, "a list of 3 numbers");
  return {xyz[0].number(), xyz[1].number(), xyz[2].number()};
}

glm::dvec3 read_color(const DocumentNode& node) {
  const std::vector<DocumentNode> rgb = node.items(3, "[r, g, b] with components >= 0");
  return {rgb[0].non_negative(), rgb[1].non_negative(), rgb[2].non_negative()};
}

glm::dvec3 read_direction(const DocumentNode& node) {
  const glm::dvec3 v = read_vec3(node);
  if (glm::length(v) == 0.0) node.fail("expected a non-zero vector");
  return v;
}

glm::dvec3 read_target(const DocumentNode& node, const glm::dvec3& position) {
  const glm::dvec3 target = read_vec3(node.required("look_at"));
  if (target == position) node.required("look_at").fail("expected a point different from \"position\"");
  return target;
}

Origin origin_of(const DocumentNode& node) { return {node.source().name(), node.path()}; }

}  // namespace matrender
