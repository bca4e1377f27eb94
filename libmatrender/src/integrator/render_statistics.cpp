#include "integrator/render_statistics.h"

#include <cmath>

namespace matrender {

RenderStats render_statistics(const std::vector<SampleCounts>& tiles, double seconds, bool cancelled) {
  SampleCounts total;
  for (const SampleCounts& tile : tiles) total.add(tile);
  RenderStats stats;
  stats.seconds = seconds;
  stats.camera_samples = total.samples;
  stats.rays = total.rays;
  stats.discarded_samples = total.discarded;
  stats.cancelled = cancelled;
  stats.occlusion_max_standard_error = total.occlusion.max_error;
  if (total.occlusion.pixels > 0)
    stats.occlusion_rms_standard_error = std::sqrt(total.occlusion.squared_error / total.occlusion.pixels);
  return stats;
}

}  // namespace matrender
