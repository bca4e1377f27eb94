#pragma once
// The sheen lobe of Cycles 3.4's Principled BSDF (kernel/closure/bsdf_principled_sheen.h, Burley
// 2012): f cos = weight (1 - L.H)^5 cos(theta_i), with no 1/pi, sampled cosine-weighted. Cycles
// labels it diffuse, so its bounces count as diffuse ones. Its weight in the mixture is the
// closure's average times the lobe's value with H at the normal, schlick(N.V) N.V
// (calculate_avg_principled_sheen_brdf), which vanishes toward normal incidence.
#include <glm/glm.hpp>

#include "bsdf/bxdf_flags.h"
#include "bsdf/lobe_sample.h"
#include "bsdf/principled_diffuse.h"
#include "util/channel_average.h"

namespace matrender {

class SheenLobe {
 public:
  SheenLobe() = default;
  // weight: the closure weight, sheen (1 - metallic) mix(1, base tint, sheen_tint).
  SheenLobe(const glm::vec3& weight, const glm::vec3& wo) : weight_(weight), wo_(wo) {}

  static constexpr BxDFFlags flags() { return BxDFFlags::DiffuseReflection; }
  float sample_weight() const {
    const float average = channel_average(weight_);
    return wo_.z > 0.0f ? average * schlick_weight(wo_.z) * wo_.z : 0.0f;
  }

  glm::vec3 eval(const glm::vec3& wi, float* pdf) const {
    *pdf = diffuse_pdf(wo_, wi);
    if (wi.z <= 0.0f || wo_.z <= 0.0f) return glm::vec3(0.0f);
    const glm::vec3 half = wo_ + wi;
    const float length = glm::length(half);
    // wi opposite wo has no half vector: L.H is then 0 in the limit, f at its largest.
    const float cos_lh = length > 0.0f ? glm::dot(wi, half) / length : 0.0f;
    return weight_ * (schlick_weight(cos_lh) * wi.z);
  }

  bool sample(glm::vec2 u, LobeSample* out) const { return sample_diffuse_lobe(wo_, u, out); }

 private:
  glm::vec3 weight_{0.0f};
  glm::vec3 wo_{0.0f, 0.0f, 1.0f};
};

}  // namespace matrender
