#pragma once
// Cycles' transparent BSDF (kernel/closure/bsdf_transparent.h), which the Principled BSDF's Alpha
// input mixes in with weight 1 - alpha: light passes straight through, wi = -wo, as if the
// surface were not there. A delta lobe; the integrator counts it as a transparent bounce, not as
// a bounce, and shadow rays pass such surfaces attenuated by the same weight.
#include <glm/glm.hpp>

#include "bsdf/bxdf_flags.h"
#include "bsdf/lobe_sample.h"
#include "util/channel_average.h"

namespace matrender {

class TransparentLobe {
 public:
  TransparentLobe() = default;
  explicit TransparentLobe(const glm::vec3& weight, const glm::vec3& wo) : weight_(weight), wo_(wo) {}

  static constexpr BxDFFlags flags() { return BxDFFlags::TransparentTransmission; }
  float sample_weight() const { return channel_average(weight_); }

  glm::vec3 eval(const glm::vec3& /*wi*/, float* pdf) const {
    *pdf = 0.0f;
    return glm::vec3(0.0f);
  }

  bool sample(glm::vec2 /*u*/, LobeSample* out) const {
    out->wi = -wo_;
    out->specular_weight = weight_;
    return true;
  }

 private:
  glm::vec3 weight_{0.0f};
  glm::vec3 wo_{0.0f, 0.0f, 1.0f};
};

}  // namespace matrender
