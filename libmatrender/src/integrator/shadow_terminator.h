#pragma once
// Cycles' shadow terminator geometry offset (Blender 3.4, kernel/light/sample.h:
// shadow_ray_offset and shadow_ray_smooth_surface_offset), after Hanika 2021, "Hacking the
// Shadow Terminator", Ray Tracing Gems II, chapter 4. A smooth-shaded triangle stands for the
// curved surface its vertex normals describe; a shadow ray leaving the flat triangle near the
// terminator is blocked by neighbouring facets and draws them. Starting it from the curved
// surface instead removes the facets.
#include <algorithm>
#include <array>
#include <limits>

#include <glm/glm.hpp>

namespace matrender {

// How much of the offset a shadow ray toward unit direction l takes, for the cutoff (Cycles'
// "Geometry Offset"): all of it close to the terminator, none well inside the lit side, with a
// smooth transition. n_dot_l = |shading normal . l|, ng_dot_l = geometric normal (on the side
// of l for reflection, of -l for transmission) . l.
inline float shadow_terminator_offset_amount(float n_dot_l, float ng_dot_l, float cutoff) {
  const float amount = n_dot_l < cutoff ? 2.0f - (ng_dot_l + n_dot_l) / cutoff : 1.0f - ng_dot_l / cutoff;
  return std::clamp(amount, 0.0f, 1.0f);
}

// The vector from the point with barycentric weights w on the flat triangle v (vertex normals
// n, unit) to the curved surface: a parabolic patch through the vertices whose normals there
// are n (Hanika's eq. for h along the interpolated normal), kept within the local linear
// envelope of the vertices' tangent planes. ng is the geometric normal on the side the ray
// leaves; a shading normal on the other side of the triangle (a back face) lowers the point.
inline glm::vec3 smooth_surface_offset(const std::array<glm::vec3, 3>& v, const std::array<glm::vec3, 3>& n,
                                       const glm::vec3& w, const glm::vec3& ng) {
  const glm::vec3 p = w.x * v[0] + w.y * v[1] + w.z * v[2];
  const glm::vec3 normal = w.x * n[0] + w.y * n[1] + w.z * n[2];  // not normalised, as Cycles
  const float a = glm::dot(n[2] - n[0], v[0] - v[2]);
  const float b = glm::dot(n[2] - n[1], v[1] - v[2]);
  const float c = glm::dot(n[1] - n[0], v[1] - v[0]);
  float h = a * w.x * (w.x - 1.0f) + (a + b + c) * w.x * w.y + b * w.y * (w.y - 1.0f);
  // Height of each vertex's tangent plane above the point, plus how far the other vertices
  // rise above that plane (or, for the lowering case, sink below it).
  const float sign = glm::dot(normal, ng) > 0.0f ? 1.0f : -1.0f;
  float envelope = std::numeric_limits<float>::max();
  for (int i = 0; i < 3; ++i) {
    const glm::vec3& other1 = v[(i + 1) % 3];
    const glm::vec3& other2 = v[(i + 2) % 3];
    const float rise = std::max(
        std::max(sign * glm::dot(other1 - v[i], n[i]), sign * glm::dot(other2 - v[i], n[i])), 0.0f);
    envelope = std::min(envelope, std::max(sign * glm::dot(v[i] - p, n[i]) + rise, 0.0f));
  }
  h = sign > 0.0f ? std::max(envelope, 0.5f * h) : std::min(-envelope, 0.5f * h);
  return normal * h;
}

}  // namespace matrender
