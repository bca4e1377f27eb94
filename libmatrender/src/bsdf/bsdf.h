#pragma once
// A shading point's BSDF in world space: its lobes (lobe_mixture.h) in the shading frame, and the
// geometric normal. Which lobes a direction scatters into follows the shading frame, as in pbrt
// and Cycles: reflecting lobes above the shading normal's plane, transmitting ones below. A
// sampled direction must also lie on its lobe's side of the geometric surface, or it is
// rejected: every Cycles 3.4 closure's sample() drops a reflection below Ng. Rays then always
// start on the side their lobe scatters to (docs/conventions.md, "Light-tight transport").
#include <glm/glm.hpp>

#include "bsdf/lobe_mixture.h"
#include "bsdf/shading_frame.h"

namespace matrender {

class Bsdf {
 public:
  // geometric_normal: unit, on the viewer's side; frame.z is the shading normal. The lobes are
  // added in place by the material (principled.h), which ends with lobes().finish().
  Bsdf(const ShadingFrame& frame, const glm::vec3& geometric_normal)
      : frame_(frame), geometric_normal_(geometric_normal) {}

  LobeMixture& lobes() { return lobes_; }
  BxDFFlags flags() const { return lobes_.flags(); }

  // f cos, and the mixture pdf of sampling wi, over the lobes that can scatter into world
  // direction wi; *side receives which kind those are (Reflection or Transmission).
  glm::vec3 eval(const glm::vec3& wi, float* pdf, BxDFFlags* side) const {
    const glm::vec3 local = frame_.to_local(wi);
    *side = local.z >= 0.0f ? BxDFFlags::Reflection : BxDFFlags::Transmission;
    return lobes_.eval(local, *side, pdf);
  }

  // A world direction from the mixture; false when none was made or when it lies on the side of
  // the geometric surface its lobe cannot scatter to.
  bool sample(glm::vec2 u, BsdfSample* out) const {
    if (!lobes_.sample(u, out)) return false;
    out->wi = frame_.to_world(out->wi);
    const bool above = glm::dot(out->wi, geometric_normal_) >= 0.0f;
    return above ? is_reflective(out->flags) : is_transmissive(out->flags);
  }

 private:
  ShadingFrame frame_;
  glm::vec3 geometric_normal_;
  LobeMixture lobes_;
};

}  // namespace matrender
