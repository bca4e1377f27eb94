#pragma once
// Ambient occlusion at a camera ray's first hit, as Cycles' Ambient Occlusion node computes it
// (distance d, "Only Local" off): the fraction of cosine-distributed directions about the
// shading normal along which no surface lies within d. Each camera sample that hits traces a
// few rays, a fixed number or as many as the pixel's error bound still needs; the directions of
// all rays of a pixel are one Owen-scrambled Sobol sequence, so they stratify the hemisphere
// across the pixel's samples. Every surface occludes whatever its opacity: Cycles traces the
// node's rays as opaque shadow rays too.
#include <algorithm>
#include <cmath>
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

// Where a pixel's occlusion rays start: a hit's position and its two normals.
struct OcclusionSite {
  glm::vec3 position{0.0f};
  glm::vec3 geometric_normal{0.0f, 0.0f, 1.0f};
  glm::vec3 shading_normal{0.0f, 0.0f, 1.0f};

  static OcclusionSite of(const SurfacePoint& sp) { return {sp.position, sp.geometric_normal, sp.shading_normal}; }
};

// A pixel's occlusion rays so far: how many it traced (or counted occluded by the surface
// itself) and how many of them escaped. The estimate is escaped / trials.
struct OcclusionTally {
  uint32_t trials = 0;
  uint32_t escaped = 0;

  // The estimate's standard error as that of Bernoulli trials, sqrt(p (1 - p) / n), with p
  // regularised to (escaped + 1) / (trials + 2) (Laplace's rule of succession) so that a run of
  // equal outcomes does not read as certainty. Stratified directions make the true error smaller.
  double standard_error() const {
    const double p = (escaped + 1.0) / (trials + 2.0);
    return trials > 0 ? std::sqrt(p * (1.0 - p) / trials) : 0.5;
  }
  // The trials still missing for a standard error of at most `error`, at the p above.
  double trials_missing(double error) const {
    const double p = (escaped + 1.0) / (trials + 2.0);
    return p * (1.0 - p) / (error * error) - trials;
  }
};

// Rays a pixel's hit traces toward a standard error of `error` by the end of its samples
// (RenderSettings::ambient_occlusion_error): a pilot of 4 at its first hit, then the trials still
// missing spread over this hit and those expected in the samples after it (samples_left - 1 of
// them, at the pixel's hit rate so far, (hits + 1) / (samples + 2)); 0 once the pixel has them.
// `samples` and `hits` count this sample; samples_left counts it too. Spreading the rays over the
// hits averages occlusion over the pixel; what a pixel still misses after its last sample, its
// last hit traces (top_up_occlusion).
inline int occlusion_rays_per_hit(const OcclusionTally& tally, uint32_t samples, uint32_t hits,
                                  uint32_t samples_left, double error) {
  if (tally.trials == 0) return 4;
  const double missing = tally.trials_missing(error);
  if (missing <= 0.0) return 0;
  const double expected_hits = 1.0 + (samples_left - 1.0) * (hits + 1.0) / (samples + 2.0);
  return static_cast<int>(std::ceil(missing / expected_hits));
}

// Traces `count` more of the pixel's occlusion rays from `site` into `tally`: the trials that
// meet nothing within `distance` escape. Ray k of the pixel uses point k of its sequence. A
// direction below the geometric surface (possible about a bent shading normal) is occluded by the
// surface itself and traces no ray. Counts the rays traced into *rays_traced.
inline void trace_occlusion_rays(const EmbreeScene& accel, const OcclusionSite& site, float distance,
                                 const PairSeeds& seeds, int count, OcclusionTally& tally, uint32_t* rays_traced) {
  const ShadingFrame frame = ShadingFrame::from_normal(site.shading_normal);
  const glm::vec3 origin = offset_ray_origin(site.position, site.geometric_normal);
  for (int k = 0; k < count; ++k, ++tally.trials) {
    const glm::vec2 u = owen_sobol_2d_reversed_index(reverse_bits(tally.trials), seeds);
    const glm::vec3 dir = frame.to_world(sample_cosine_hemisphere(u));
    if (!(glm::dot(dir, site.geometric_normal) > 0.0f)) continue;
    ++*rays_traced;
    if (!accel.occluded(origin, dir, distance)) ++tally.escaped;
  }
}

// Traces from `site`, the pixel's last hit, what the tally still misses for standard error
// `error`, asking again as its estimate moves, so that every pixel a sample hit ends within it.
inline void top_up_occlusion(const EmbreeScene& accel, const OcclusionSite& site, float distance, const PairSeeds& seeds,
                             double error, OcclusionTally& tally, uint32_t* rays_traced) {
  for (double missing = tally.trials_missing(error); missing > 0.0; missing = tally.trials_missing(error))
    trace_occlusion_rays(accel, site, distance, seeds, static_cast<int>(std::ceil(missing)), tally, rays_traced);
}

// Ambient occlusion as a render asks for it (RenderSettings): at every hit of a pixel's camera
// samples a fixed number of rays, or, with an error bound, as many as the pixel still needs
// (occlusion_rays_per_hit), and after the pixel's samples what the bound still misses.
class AmbientOcclusionEstimator {
 public:
  AmbientOcclusionEstimator(const EmbreeScene& accel, float distance, double error, int rays_per_hit)
      : accel_(accel), distance_(distance), error_(error), rays_per_hit_(rays_per_hit) {}

  // At the hit `site` of a pixel's camera sample: `samples` and `hits` count this sample, and
  // samples_left counts it too. Returns the rays traced.
  uint32_t at_hit(OcclusionTally& tally, const OcclusionSite& site, const PairSeeds& seeds, uint32_t samples,
                  uint32_t hits, uint32_t samples_left) const {
    const int rays = error_ > 0.0 ? occlusion_rays_per_hit(tally, samples, hits, samples_left, error_) : rays_per_hit_;
    uint32_t traced = 0;
    trace_occlusion_rays(accel_, site, distance_, seeds, rays, tally, &traced);
    return traced;
  }

  // After a run of a pixel's samples, `hits` of which hit, the last at `last_hit`: with an error
  // bound, the trials the tally still misses. Returns the rays traced.
  uint32_t after_samples(OcclusionTally& tally, const OcclusionSite& last_hit, const PairSeeds& seeds, int32_t hits) const {
    if (!(error_ > 0.0) || hits == 0) return 0;
    uint32_t traced = 0;
    top_up_occlusion(accel_, last_hit, distance_, seeds, error_, tally, &traced);
    return traced;
  }

 private:
  const EmbreeScene& accel_;
  float distance_;
  double error_;
  int rays_per_hit_;
};

}  // namespace matrender
