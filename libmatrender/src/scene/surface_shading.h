#pragma once
// From a ray hit to everything shading needs: position, normals facing the viewer, UV, and the
// material's inputs after texture lookups.
#include <cstdint>
#include <optional>

#include <glm/glm.hpp>

#include "accel/embree_scene.h"
#include "bsdf/principled.h"
#include "scene/scene_data.h"

namespace matrender {

struct SurfacePoint {
  SurfacePoint() = default;
  // With the material's inputs before textures, built in place: a point is made at every path
  // vertex, and defaults that are overwritten at once cost a copy of the whole table.
  explicit SurfacePoint(const PrincipledInputs& untextured) : inputs(untextured) {}

  glm::vec3 position{0.0f};
  glm::vec3 geometric_normal{0.0f, 0.0f, 1.0f};  // flipped to face the incoming ray
  // The ray met the side the triangle's winding faces (counter-clockwise = front, as Blender).
  bool front_face = true;
  glm::vec3 shading_normal{0.0f, 0.0f, 1.0f};    // smooth + normal map, valid for reflection
  // The interpolated vertex normal before normal mapping and ensure_valid_reflection (Cycles'
  // sd->N; the geometric normal without vertex normals), flipped to face the incoming ray.
  glm::vec3 smooth_normal{0.0f, 0.0f, 1.0f};
  // What the material's normal map says in its tangent space (2 texel - 1, renormalised), read
  // whenever the material has one; (0, 0, 1), the unperturbed normal, otherwise.
  glm::vec3 tangent_space_normal{0.0f, 0.0f, 1.0f};
  glm::vec2 uv{0.0f};
  uint32_t material = 0;
  int32_t part = 0;
  uint32_t mesh = 0;  // the scene's index of the mesh hit
  PrincipledInputs inputs;

  // Radiance the surface emits toward the viewer: Cycles' emission closure, the same from both
  // sides (kernel/closure/emissive.h), scaled like every closure by the coverage (Alpha).
  glm::vec3 emitted() const {
    return inputs.color(MaterialParameter::Emission) *
           (inputs.scalar(MaterialParameter::EmissionStrength) * inputs.coverage());
  }

};

// wo = unit direction from the hit back toward the ray origin. cone_width: the width of the ray's
// cone at the hit (world units), for mip-mapped texture lookups; 0 looks textures up bilinearly.
SurfacePoint shade_surface(const SceneData& scene, const RayHit& hit, const glm::vec3& wo, float cone_width = 0.0f);

// The inputs shade_surface gives every point of `material` when none of them varies over the
// surface (no texture, no vertex colours).
std::optional<PrincipledInputs> constant_inputs(const Material& material);

}  // namespace matrender
