#pragma once
// A shading point's BSDF in world space: its lobes (lobe_mixture.h) in the shading frame, and the
// geometric normal, which alone decides whether light crosses the surface. A direction on the
// viewer's side of the geometric surface can only be reflected into, one on the far side only
// transmitted into, whatever the shading normal says (Cycles 3.4 decides the same way:
// shader_bsdf_eval with is_transmission = dot(Ng, L) < 0, and every closure's sample rejects a
// reflection below Ng). This is what keeps light from passing through a zero-thickness surface
// whose smooth normals lean toward a lamp behind it (docs/conventions.md, "Light-tight
// transport").
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

  // Which lobes a world direction can scatter into: those reflecting when wi is on the viewer's
  // side of the geometric surface (or in its plane), those transmitting otherwise.
  BxDFFlags side_of(const glm::vec3& wi) const {
    return glm::dot(wi, geometric_normal_) >= 0.0f ? BxDFFlags::Reflection : BxDFFlags::Transmission;
  }

  // f cos over the lobes of wi's side, and the mixture pdf of sampling wi, for world wi.
  glm::vec3 eval(const glm::vec3& wi, float* pdf) const { return lobes_.eval(frame_.to_local(wi), side_of(wi), pdf); }

  // A world direction from the mixture; false when none was made or when the picked lobe's
  // direction lies on the side of the surface that lobe cannot scatter to.
  bool sample(glm::vec2 u, BsdfSample* out) const {
    if (!lobes_.sample(u, out)) return false;
    out->wi = frame_.to_world(out->wi);
    return any(side_of(out->wi) & out->flags);
  }

 private:
  ShadingFrame frame_;
  glm::vec3 geometric_normal_;
  LobeMixture lobes_;
};

}  // namespace matrender
