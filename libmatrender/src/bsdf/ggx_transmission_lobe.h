#pragma once
// The refraction half of the Principled BSDF's glass: single-scatter GGX transmission through
// rough dielectric microfacets (Walter et al. 2007, "Microfacet Models for Refraction through
// Rough Surfaces", eq. 21), as Cycles 3.4's CLOSURE_BSDF_MICROFACET_GGX_REFRACTION_ID
// (kernel/closure/bsdf_microfacet.h, bsdf_microfacet_ggx_eval_transmit and _sample):
//   f cos = w |wi.m| |wo.m| eta^2 D(m) G1(wo) G1(wi) / (cos_o (wo.m + eta wi.m)^2)
// with the generalised half vector m = -(wo + eta wi) / |wo + eta wi| facing +Z, eta the far
// side's index over the viewer's, and no Fresnel: the closure weight w carries
// (1 - F(N.V)) and the base colour. The eta^2 makes it the BTDF of radiance, so
// f(wo, wi) / eta^2 = f(wi, wo) seen from the far side (Veach 1997, sec. 5.2). Sampled through
// visible normals; below Cycles' singular roughness, or with eta within 1e-4 of 1, it is a
// delta refraction.
#include <cmath>

#include <glm/glm.hpp>

#include "bsdf/bxdf_flags.h"
#include "bsdf/lobe_sample.h"
#include "bsdf/microfacet_ggx.h"
#include "util/channel_average.h"

namespace matrender {

class GgxTransmissionLobe {
 public:
  GgxTransmissionLobe() = default;
  // weight: the closure weight. eta: the far side's index of refraction over the viewer's.
  GgxTransmissionLobe(const glm::vec3& weight, float eta, float alpha, const glm::vec3& wo)
      : weight_(weight),
        eta_(eta),
        alpha_(alpha),
        singular_(alpha * alpha <= kGgxSingularAlpha2 || std::abs(eta - 1.0f) < 1e-4f),
        wo_(wo),
        g1_wo_(singular_ ? 0.0f : ggx_g1(wo, alpha)) {}

  BxDFFlags flags() const { return singular_ ? BxDFFlags::SpecularTransmission : BxDFFlags::GlossyTransmission; }
  float sample_weight() const { return wo_.z > 0.0f ? channel_average(weight_) : 0.0f; }

  glm::vec3 eval(const glm::vec3& wi, float* pdf) const {
    *pdf = 0.0f;
    if (singular_ || wo_.z <= 0.0f || wi.z >= 0.0f) return glm::vec3(0.0f);
    glm::vec3 m = wo_ + eta_ * wi;
    const float length2 = glm::dot(m, m);
    if (!(length2 > 0.0f)) return glm::vec3(0.0f);
    m *= (m.z < 0.0f ? -1.0f : 1.0f) / std::sqrt(length2);
    // Only microfacets that face wo and turn away from wi refract wo into wi.
    const float wo_dot_m = glm::dot(wo_, m);
    const float wi_dot_m = glm::dot(wi, m);
    if (wo_dot_m <= 0.0f || wi_dot_m >= 0.0f) return glm::vec3(0.0f);
    const float denominator = wo_dot_m + eta_ * wi_dot_m;
    // Visible-normal density of m, G1(wo) (wo.m) D(m) / cos_o, times the refraction Jacobian
    // d omega_m / d omega_i = eta^2 |wi.m| / (wo.m + eta wi.m)^2 (Walter et al. 2007, eq. 17).
    const float jacobian = eta_ * eta_ * -wi_dot_m / (denominator * denominator);
    const float d_wo_dot_m_over_cos = ggx_d(m, alpha_) * wo_dot_m / wo_.z;
    *pdf = g1_wo_ * d_wo_dot_m_over_cos * jacobian;
    const float g1_wi = ggx_g1(glm::vec3(wi.x, wi.y, -wi.z), alpha_);
    return weight_ * (*pdf * g1_wi);
  }

  bool sample(glm::vec2 u, LobeSample* out) const {
    if (wo_.z <= 0.0f) return false;
    if (singular_) {
      if (!refract_about(wo_, glm::vec3(0.0f, 0.0f, 1.0f), eta_, &out->wi)) return false;
      out->specular_weight = weight_;
      return true;
    }
    const glm::vec3 m = ggx_sample_visible_normal(wo_, alpha_, u);
    return refract_about(wo_, m, eta_, &out->wi) && out->wi.z < 0.0f;
  }

 private:
  glm::vec3 weight_{0.0f};
  float eta_ = 1.5f;
  float alpha_ = 0.0f;
  bool singular_ = true;
  glm::vec3 wo_{0.0f, 0.0f, 1.0f};
  float g1_wo_ = 0.0f;
};

}  // namespace matrender
