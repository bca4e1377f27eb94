#pragma once
// Ambient occlusion at a camera ray's first hit, as Cycles' Ambient Occlusion node computes it
// (distance d, "Only Local" off): the fraction of cosine-distributed directions about the
// shading normal along which no surface lies within d. Each camera sample that hits traces a
// few rays; the directions of all rays of a pixel are one Owen-scrambled Sobol sequence, so they
// stratify the hemisphere across the pixel's samples. Every surface occludes whatever its
// opacity: Cycles traces the node's rays as opaque shadow rays too.
#include <cstdint>

#include <glm/glm.hpp>

#include "accel/embree_scene.h"
#include "accel/ray_offset.h"
#include "bsdf/shading_frame.h"
#include "sampling/owen_sobol.h"
#include "sampling/warp.h"
#include "scene/surface_shading.h"

namespace matrender {

// The seeds of a pixel's occlusion directions: apart from the path's dimension pairs, so adding
// the AOV leaves the colour unchanged.
inline PairSeeds ambient_occlusion_seeds(uint32_t pixel_index, uint32_t global_seed) {
  constexpr uint32_t kSalt = 0x41f0c5d3u;
  return PairSeeds(hash_combine(hash_combine(hash_u32(pixel_index), global_seed), kSalt));
}

// How many of `count` rays from `sp` meet nothing within `distance`; ray k uses point
// first_index + k of the pixel's sequence. A direction below the geometric surface (possible
// about a bent shading normal) is occluded by the surface itself and traces no ray.
inline int unoccluded_rays(const EmbreeScene& accel, const SurfacePoint& sp, float distance, const PairSeeds& seeds,
                           uint32_t first_index, int count, uint32_t* rays_traced) {
  const ShadingFrame frame = ShadingFrame::from_normal(sp.shading_normal);
  const glm::vec3 origin = offset_ray_origin(sp.position, sp.geometric_normal);
  int unoccluded = 0;
  for (int k = 0; k < count; ++k) {
    const glm::vec2 u = owen_sobol_2d_reversed_index(reverse_bits(first_index + static_cast<uint32_t>(k)), seeds);
    const glm::vec3 dir = frame.to_world(sample_cosine_hemisphere(u));
    if (!(glm::dot(dir, sp.geometric_normal) > 0.0f)) continue;
    ++*rays_traced;
    if (!accel.occluded(origin, dir, distance)) ++unoccluded;
  }
  return unoccluded;
}

}  // namespace matrender
