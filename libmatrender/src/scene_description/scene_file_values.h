#pragma once
// The small values every part of a scene file (docs/scene_format.md) reads, through
// matbase::DocumentNode so that each refusal names the file and the JSON pointer of the value
// ("scene.json: /lights/2/color/0: expected a number of at least 0, got -1"). The scene file's
// reader and each light's own reader (lights/lamp_preparation.h) use them.
#include <glm/glm.hpp>

#include "matbase/document/document_node.h"
#include "matrender/scene_description.h"

namespace matrender {

glm::dvec3 read_vec3(const matbase::DocumentNode& node);
glm::dvec3 read_color(const matbase::DocumentNode& node);      // [r, g, b], each >= 0
glm::dvec3 read_direction(const matbase::DocumentNode& node);  // non-zero
// The node's "look_at", which must differ from `position`.
glm::dvec3 read_target(const matbase::DocumentNode& node, const glm::dvec3& position);

// Where the node's value came from, kept in the description for what only loading finds.
Origin origin_of(const matbase::DocumentNode& node);

}  // namespace matrender
