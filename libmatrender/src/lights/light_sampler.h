#pragma once
// How a lamp is chosen for next-event estimation: uniformly, one lamp per shading point, as
// Cycles 3.4 does (it has no light tree). Only noise depends on this choice.
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "lights/light_sample.h"
#include "lights/rect_light.h"
#include "lights/rect_light_hits.h"
#include "lights/spot_light.h"
#include "matrender/light.h"

namespace matrender {

class LightSampler {
 public:
  explicit LightSampler(const std::vector<Light>& lights);

  bool empty() const { return count() == 0; }
  size_t count() const { return rects_.size() + deltas_.size(); }
  float selection_pdf() const { return empty() ? 0.0f : 1.0f / static_cast<float>(count()); }

  // A sample of one uniformly chosen lamp; its pdf includes the selection probability. u.x
  // picks the lamp and is then rescaled to [0, 1) within the lamp's interval and reused for the
  // point on it, so each lamp's points keep the 2-D stratification of u (Cycles 3.4,
  // kernel/light/light.h, light_distribution_sample: "rescale to reuse random number").
  // Lamps wholly outside `receiving` give no sample (see PreparedRectLight).
  std::optional<LightSample> sample(const glm::vec3& p, const ReceivingDirections& receiving, glm::vec2 u) const;

  const std::vector<PreparedRectLight>& rect_lights() const { return rects_; }
  const RectLightHits& rect_light_hits() const { return rect_hits_; }

 private:
  std::vector<PreparedRectLight> rects_;
  std::vector<PreparedDeltaLight> deltas_;
  RectLightHits rect_hits_;
};

}  // namespace matrender
