#pragma once
// Unidirectional path tracing with next-event estimation and MIS (docs/conventions.md).
#include <cstdint>

#include "matrender/camera.h"
#include "matrender/frame.h"
#include "matrender/render_setting_declarations.h"
#include "matrender/render_settings.h"
#include "matrender/scene.h"

namespace matrender {

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
  // With a target error: the frame's relative RMSE over the covered pixels as predicted when
  // sampling stopped (docs/conventions.md, "Rendering to an error").
  double predicted_error = 0.0;
};

// The fewest camera samples a pixel of a complete render takes under these settings:
// samples_per_pixel, or, with adaptive sampling, the count of the first check if it is fewer.
int fewest_samples_per_pixel(const RenderSettings& settings);

// Renders `scene` (committing it if needed) through `camera` into `frame` (resized to the
// camera's resolution). Thread-safe for concurrent renders of one committed scene. Settings a
// reader did not check are checked first (render_settings_problem; std::invalid_argument).
RenderStats render(Scene& scene, const Camera& camera, const RenderSettings& settings,
                   FrameBuffers& frame);

}  // namespace matrender
