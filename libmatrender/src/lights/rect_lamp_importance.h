#pragma once
// Light selection's weight (light_importance.h) of every rectangular lamp at one shading point,
// in one pass over the lamps' bounds laid out one array per quantity, so that the loop compiles
// to vector instructions (four lamps to an SSE instruction). Evaluated one lamp at a time it was
// the largest cost of a path vertex after Embree's traversal: at the paper's eight lamps, about
// 1,200 of the 5,600 instructions a sample of render_bench's sphere (callgrind).
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "lights/light_sample.h"
#include "lights/rect_light.h"

namespace matrender {

class RectLampImportance {
 public:
  RectLampImportance() = default;
  explicit RectLampImportance(const std::vector<RectLight>& lamps);

  size_t size() const { return power_.size(); }

  // weights[i] = lamps[i].importance(p, receiving) for every lamp (weights holds size()).
  void evaluate(const glm::vec3& p, const ReceivingDirections& receiving, float* weights) const;

 private:
  // Per lamp: the centre, the lamp's +Z (the side that does not emit), the bounding radius and
  // the power, as RectLight::importance reads them.
  std::vector<float> center_x_, center_y_, center_z_;
  std::vector<float> back_x_, back_y_, back_z_;
  std::vector<float> radius_, power_;
};

}  // namespace matrender
