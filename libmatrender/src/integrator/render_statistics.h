#pragma once
// What a render counts as it goes: each tile's samples, rays and discarded samples, and its
// pixels' ambient-occlusion errors; summed in tile order at the end (render_statistics), so the
// figures do not depend on which thread finished first.
#include <cstdint>
#include <vector>

#include "film/film.h"
#include "matrender/render.h"

namespace matrender {

struct SampleCounts {
  uint64_t samples = 0;
  uint64_t rays = 0;
  uint64_t discarded = 0;  // samples whose radiance was NaN or infinite
  OcclusionFigures occlusion;

  void add(const SampleCounts& other) {
    samples += other.samples;
    rays += other.rays;
    discarded += other.discarded;
    occlusion.add(other.occlusion);
  }
};

// The statistics of a render whose tiles counted `tiles`.
RenderStats render_statistics(const std::vector<SampleCounts>& tiles, double seconds, bool cancelled);

}  // namespace matrender
