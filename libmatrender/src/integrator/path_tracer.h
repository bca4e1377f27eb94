#pragma once
// Unidirectional path tracing with next-event estimation and multiple importance sampling
// (Veach 1997, ch. 9), bounce limits and Russian roulette as Cycles 3.4 applies them.
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "lights/light_sampler.h"
#include "matrender/render_settings.h"
#include "sampling/pixel_sampler.h"
#include "scene/scene_data.h"
#include "scene/surface_shading.h"

namespace matrender {

// What the path tracer follows of a render's settings (matrender/render_settings.h, whose
// declarations give each one's meaning, range and default). Cycles parity reproduces Cycles 3.4's
// own estimators, and looks textures up bilinearly as Cycles 3.4 on the CPU does.
struct PathSettings {
  PathSettings(const RenderSettings& settings, float camera_pixel_spread_angle);

  int max_bounces;
  int max_diffuse_bounces;
  int max_glossy_bounces;
  int max_transmission_bounces;
  int max_transparent_bounces;
  bool transparent_background;
  ClearcoatEstimator clearcoat_estimator;
  MultiscatterWalk multiscatter_walk;
  // The angle a camera ray's cone spreads by (about a pixel's); 0 turns mip-mapping off. Cones
  // continue through specular bounces and transparent passes; after any other bounce a lookup's
  // footprint is a camera pixel's at that distance from the camera.
  float pixel_spread_angle;
};

struct PathResult {
  glm::vec3 radiance{0.0f};
  bool hit = false;           // the camera ray hit a surface
  float transparency = 0.0f;  // of the camera ray through transparent surfaces to the background (1: a miss)
  float first_distance = 0.0f;
  uint32_t rays = 0;          // closest-hit and shadow rays traced after the camera's
};

class PathTracer {
 public:
  PathTracer(const SceneData& scene, const LightSampler& lights, const PathSettings& settings);

  // Radiance along the camera ray, whose closest hit the caller traced (camera rays go to
  // Embree in packets); random numbers come from `sampler` pairs 1, 2, ... (pair 0 is the
  // caller's pixel-filter offset). When the camera ray hits and first_surface is given, the
  // surface it hit is copied there (for the AOVs): a caller without AOVs pays for no copy.
  PathResult trace(const glm::vec3& origin, const glm::vec3& dir, const RayHit& camera_hit,
                   const PixelSampler& sampler, SurfacePoint* first_surface = nullptr) const;

 private:
  // What reaches origin + distance dir from origin: 0 behind an opaque surface, 1 - alpha through
  // each transparent one. Counts the rays it traces into *rays.
  glm::vec3 transmittance(const glm::vec3& origin, const glm::vec3& dir, float distance, uint32_t* rays) const;

  // Every emitter the ray from origin along dir finds, times throughput, added to radiance: the
  // area lamps it passes before its hit, then the emitting surface it hits (`surface`, shaded at
  // `hit`) or, when it hits nothing, the infinite lights it sees (unless the camera's ray and a
  // transparent background). The one path for every light a ray can reach, each weighed by
  // LightSampler::found_light_weight.
  void add_emitters_found(glm::vec3& radiance, const glm::vec3& throughput, const glm::vec3& origin,
                          const glm::vec3& dir, const RayHit& hit, const SurfacePoint* surface,
                          const ScatteredRay& ray) const;

  const SceneData& scene_;
  const LightSampler& lights_;
  PathSettings settings_;
  // Per material: its lobes' parameters when no input is textured (computed once, not at every hit).
  std::vector<std::optional<PrincipledParameters>> constant_parameters_;
  // Some material has alpha below 1 or from a texture: shadow rays must look through surfaces.
  bool has_transparency_ = false;
};

}  // namespace matrender
