#pragma once
// Unidirectional path tracing with next-event estimation and MIS (docs/conventions.md).
#include <atomic>
#include <cstdint>
#include <functional>

#include "matrender/camera.h"
#include "matrender/frame.h"
#include "matrender/scene.h"

namespace matrender {

// How next-event estimation picks one light per shading point: in proportion to a bound on the
// irradiance each light can give there (0 where it can give none), or uniformly as Cycles 3.4
// does. Only the noise differs.
enum class LightSelection { Importance, Uniform };

// The error bound ambient occlusion can be asked for (RenderSettings::ambient_occlusion_error):
// below the least, its worst case, 0.25 / error^2, exceeds 250,000 rays per pixel; above the most,
// a pixel's estimate says nothing (the value itself lies in [0, 1]).
constexpr double kMinAmbientOcclusionError = 0.001;
constexpr double kMaxAmbientOcclusionError = 0.5;

struct RenderSettings {
  int samples_per_pixel = 64;
  // Adaptive sampling as Cycles 3.4 (Noise Threshold and Min Samples; docs/conventions.md): a
  // pixel stops taking samples once its relative error estimate falls below noise_threshold and
  // its neighbours' have too; samples_per_pixel is then the most any pixel takes. 0 = off: every
  // pixel takes samples_per_pixel. min_samples: the samples before the first check, 0 = Cycles'
  // automatic max(4, ceil(16 / noise_threshold^0.3)).
  double noise_threshold = 0.0;
  int min_samples = 0;
  uint32_t seed = 0;
  int threads = 0;  // 0 = all hardware threads; the image does not depend on this
  // Cycles 3.4 defaults.
  int max_bounces = 12;
  int max_diffuse_bounces = 4;
  int max_glossy_bounces = 4;
  int max_transmission_bounces = 12;
  int max_transparent_bounces = 8;  // surfaces of alpha < 1 a ray passes, camera and shadow rays alike
  bool transparent_background = false;  // camera rays that miss give 0 instead of the background
  // Reproduce Cycles 3.4's own estimators where they do not converge to the integral of its BSDF
  // (the clearcoat's sampling, the multiscatter walk; docs/conventions.md), for parity with images
  // made in Blender. Lights are then picked uniformly whatever light_selection says: a biased
  // estimator's image depends on the MIS weights.
  bool cycles_parity = false;
  LightSelection light_selection = LightSelection::Importance;
  // Filter the colour after rendering (matrender/denoise.h), guided by AOVs the frame then holds
  // too (kDenoiseGuideAovs) whether asked for or not. Not with cycles_parity: Blender 3.4 as
  // Debian ships it has no denoiser to be on a par with.
  bool denoise = false;
  // Filter textures over each camera ray's footprint (a ray cone, continued through mirrors and
  // glass) from their mip levels, so a 4k map seen from afar does not alias; off: bilinear at the
  // hit point only, as Cycles 3.4 on the CPU (and always in cycles_parity).
  bool mipmaps = true;
  uint32_t aovs = default_aovs();
  // Ambient occlusion (AovAmbientOcclusion): how far a surface may be to occlude (Cycles' AO
  // node: 1 m), and how many rays each camera sample that hits traces from its hit. With
  // ambient_occlusion_error > 0 each pixel traces as many as its own trials show it needs for a
  // standard error of at most that (ambient_occlusion.h: a Bernoulli bound with the pixel's
  // regularised estimate; open surfaces need far fewer than half-occluded ones), and
  // ambient_occlusion_rays is not used. Otherwise every hit traces ambient_occlusion_rays, and
  // a pixel's standard error is at most 0.5 / sqrt(hits x rays) (less: the directions are
  // stratified). The error is 0 or in [kMinAmbientOcclusionError, kMaxAmbientOcclusionError].
  double ambient_occlusion_distance = 1.0;
  double ambient_occlusion_error = 0.0;
  int ambient_occlusion_rays = 4;
  // Called with the finished fraction of all samples in [0, 1], from a render thread, every 65,536
  // samples a thread takes and when a tile ends; calls are serialised and the fraction increases.
  std::function<void(double)> progress;
  // Checked at every packet of 16 samples; when it becomes true the render stops within
  // milliseconds and reports cancelled (the frame is then incomplete).
  const std::atomic<bool>* cancel = nullptr;
};

struct RenderStats {
  double seconds = 0.0;
  // Every sample a pixel took, those of pixels that cannot see the scene (which need no ray) too.
  uint64_t camera_samples = 0;
  uint64_t rays = 0;               // closest-hit and shadow rays traced
  uint64_t discarded_samples = 0;  // path contributions that were NaN or Inf and were dropped
  // Ambient occlusion's estimated standard error (OcclusionTally) over the pixels a sample hit:
  // the root mean square and the largest.
  double occlusion_rms_standard_error = 0.0;
  double occlusion_max_standard_error = 0.0;
  bool cancelled = false;
};

// The fewest camera samples a pixel of a complete render takes under these settings:
// samples_per_pixel, or, with adaptive sampling, the count of the first check if it is fewer.
int fewest_samples_per_pixel(const RenderSettings& settings);

// Renders `scene` (committing it if needed) through `camera` into `frame` (resized to the
// camera's resolution). Thread-safe for concurrent renders of one committed scene.
RenderStats render(Scene& scene, const Camera& camera, const RenderSettings& settings,
                   FrameBuffers& frame);

}  // namespace matrender
