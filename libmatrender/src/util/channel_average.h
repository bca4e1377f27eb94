#pragma once
#include <glm/glm.hpp>

namespace matrender {

// The mean of a colour's channels, Cycles' average(): closure pick weights, the weight cutoff,
// the film's transparency.
inline float channel_average(const glm::vec3& c) { return (c.x + c.y + c.z) / 3.0f; }

}  // namespace matrender
