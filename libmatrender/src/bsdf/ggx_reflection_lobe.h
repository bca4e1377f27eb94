#pragma once
// The specular lobe of the Principled BSDF, and the reflection half of its glass: single-scatter
// GGX reflection (microfacet_ggx.h) with Cycles' interpolated Fresnel (fresnel.h) times a closure
// weight, sampled from the visible normals. Below Cycles' singular roughness it is a perfect
// mirror: a specular (delta) lobe.
#include <algorithm>

#include <glm/glm.hpp>

#include "bsdf/bxdf_flags.h"
#include "bsdf/fresnel.h"
#include "bsdf/lobe_sample.h"
#include "bsdf/microfacet_ggx.h"
#include "util/channel_average.h"

namespace matrender {

class GgxReflectionLobe {
 public:
  // weight: the closure weight (1 - transmission (1 - metallic) for the specular lobe, the glass
  // weight times F(N.V) for the glass's reflection).
  GgxReflectionLobe(float weight, const InterpolatedFresnel& fresnel, float alpha, bool singular, const glm::vec3& wo)
      : weight_(weight),
        fresnel_(fresnel),
        alpha_(alpha),
        singular_(singular),
        wo_(wo),
        g1_wo_over_4cos_(singular ? 0.0f : ggx_g1(wo, alpha) / (4.0f * wo.z)) {}

  BxDFFlags flags() const { return singular_ ? BxDFFlags::SpecularReflection : BxDFFlags::GlossyReflection; }
  // Cycles weights the pick by the Fresnel reflectance toward the viewer.
  float sample_weight() const {
    const glm::vec3 f = fresnel_(std::max(wo_.z, 0.0f));
    return weight_ * channel_average(f);
  }

  glm::vec3 eval(const glm::vec3& wi, float* pdf) const {
    *pdf = 0.0f;
    if (singular_ || wo_.z <= 0.0f || wi.z <= 0.0f) return glm::vec3(0.0f);
    const glm::vec3 m = glm::normalize(wo_ + wi);
    // D G1(wo) / (4 cos_o) is both the visible-normal sampling pdf of wi (ggx_reflection_pdf)
    // and, times F G1(wi), the value f cos = F D G / (4 cos_o cos_i) * cos_i.
    const float d_g1_over_4cos = ggx_d(m, alpha_) * g1_wo_over_4cos_;
    *pdf = d_g1_over_4cos;
    return fresnel_(glm::dot(wi, m)) * (weight_ * d_g1_over_4cos * ggx_g1(wi, alpha_));
  }

  bool sample(glm::vec2 u, LobeSample* out) const {
    if (wo_.z <= 0.0f) return false;
    if (singular_) {
      out->wi = glm::vec3(-wo_.x, -wo_.y, wo_.z);
      out->specular_weight = weight_ * fresnel_(wo_.z);
      return true;
    }
    out->wi = reflect_about(wo_, ggx_sample_visible_normal(wo_, alpha_, u));
    return out->wi.z > 0.0f;
  }

 private:
  float weight_;
  InterpolatedFresnel fresnel_;
  float alpha_;
  bool singular_;
  glm::vec3 wo_;
  float g1_wo_over_4cos_;  // Smith G1(wo) / (4 cos_o), shared by every evaluation
};

}  // namespace matrender
