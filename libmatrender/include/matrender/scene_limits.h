#pragma once
// What single-precision rendering can represent. Embree traverses and the renderer shades in
// 32-bit floats, which resolve a coordinate to 2^-23 of its magnitude: 8 mm or better within
// kMaxSceneCoordinate of the origin, 1 m at 8,400 km, and Embree itself asserts on rays that
// start beyond 1.8e18. Geometry, lamps and cameras beyond the limit are refused, with it stated,
// instead of rendering wrongly or crashing.
#include <optional>
#include <string>

#include <glm/glm.hpp>

namespace matrender {

constexpr double kMaxSceneCoordinate = 65536.0;  // metres; float spacing there is 2^-7 m

// `point` is finite and each of its coordinates lies within +-kMaxSceneCoordinate.
bool within_scene_limit(const glm::dvec3& point);

// "<what> at (x, y, z) lies beyond ..." unless `point` is finite and each of its coordinates lies
// within +-kMaxSceneCoordinate; nothing when it does.
std::optional<std::string> scene_point_problem(const glm::dvec3& point, const std::string& what);

// Throws std::invalid_argument with that problem, if any.
void check_scene_point(const glm::dvec3& point, const std::string& what);

}  // namespace matrender
