#pragma once
// One pixel's camera samples (pbrt-v4's RayIntegrator::EvaluatePixelSample, for a run of them):
// each sample's offset drawn from the pixel filter, the camera rays traced in packets, the path
// traced from each hit, and the radiance, coverage, first surface and ambient occlusion added to
// the pixel's sums on the film. A pixel whose rays cannot meet the scene and see a uniform
// background takes its samples without rays. Samples [a, b) then [b, c) sum as [a, c) does, so
// adaptive sampling's rounds give the image a single run would.
#include <cstdint>
#include <optional>

#include <glm/glm.hpp>

#include "film/camera_rays.h"
#include "film/film.h"
#include "film/pixel_filter.h"
#include "film/reachable_pixels.h"
#include "integrator/ambient_occlusion.h"
#include "integrator/path_tracer.h"
#include "integrator/render_control.h"
#include "integrator/render_statistics.h"
#include "scene/scene_data.h"

namespace matrender {

class PixelEvaluator {
 public:
  struct Setup {
    const SceneData& scene;
    const PathTracer& tracer;
    const CameraRays& rays;
    const PixelFilterSampler& filter;  // of the settings' width
    int width;
    uint32_t seed;
    // Camera rays of pixels outside it meet nothing.
    PixelRect pixels_seeing_scene;
    // What every camera ray that meets nothing sees, when that does not depend on its direction.
    std::optional<glm::vec3> uniform_background;
    bool second_estimate;  // adaptive sampling's
    const AmbientOcclusionEstimator* occlusion;  // null without the AOV
  };

  PixelEvaluator(const Setup& setup, Film& film, RenderControl& control)
      : setup_(setup), film_(film), control_(control), filter_(setup.filter) {}

  // Takes samples [begin, end) of pixel (x, y) into `sums`, counting into `counts` and `progress`.
  // Stops between packets of samples once the render is cancelled.
  void take_samples(int x, int y, uint32_t begin, uint32_t end, PixelSums& sums, SampleCounts& counts,
                    RenderControl::Batch& progress) const;

 private:
  // Samples [begin, end) of a pixel whose camera rays all meet nothing and see the uniform
  // background: what take_samples would sum for them, without their rays.
  void take_background_samples(uint32_t pixel, uint32_t begin, uint32_t end, PixelSums& sums, SampleCounts& counts,
                               RenderControl::Batch& progress) const;

  Setup setup_;
  Film& film_;
  RenderControl& control_;
  const PixelFilterSampler& filter_;
};

}  // namespace matrender
