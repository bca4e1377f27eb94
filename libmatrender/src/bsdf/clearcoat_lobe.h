#pragma once
// The clearcoat lobe of Cycles 3.4's Principled BSDF (CLOSURE_BSDF_MICROFACET_GGX_CLEARCOAT_ID in
// kernel/closure/bsdf_microfacet.h):
//   f cos = w F(wi.m) D_GTR1(m) G1(wo) G1(wi) / (4 cos_o),   w = 0.25 clearcoat,
// with the dielectric Fresnel of ior 1.5 (Cycles' interpolated Fresnel with cspec0 0.04 is exactly
// that), Berry's distribution of alpha = clearcoat_roughness^2 (microfacet_gtr1.h) and Smith-GGX
// shadowing at a fixed alpha of 0.25. Its normal is the smooth normal, not a normal-mapped one
// (the Clearcoat Normal input left unlinked), so it may be tilted against the shading frame.
//
// Cycles does not sample this lobe by its own pdf: it draws GGX visible normals of alpha
// clearcoat_roughness^2 and reports the pdf G1(wo) D_GTR1(m) / (4 cos_o), so its BSDF-sampled
// estimates are biased (docs/conventions.md, "Clearcoat"). ClearcoatEstimator::Integral samples
// m from D_GTR1 cos(theta_m) with that density's pdf and converges to the integral of f;
// ClearcoatEstimator::Cycles34 reproduces Cycles' sampling and pdf, for parity with images made
// in Blender.
#include <algorithm>

#include <glm/glm.hpp>

#include "bsdf/bxdf_flags.h"
#include "bsdf/fresnel.h"
#include "bsdf/lobe_sample.h"
#include "bsdf/microfacet_gtr1.h"
#include "bsdf/microfacet_ggx.h"
#include "bsdf/shading_frame.h"

namespace matrender {

enum class ClearcoatEstimator { Integral, Cycles34 };

// The clearcoat's fixed index of refraction and shadowing width (bsdf_microfacet.h: "the alpha
// value for clearcoat is a fixed 0.25").
constexpr float kClearcoatIor = 1.5f;
constexpr float kClearcoatShadowingAlpha = 0.25f;

class ClearcoatLobe {
 public:
  ClearcoatLobe() = default;
  // weight: 0.25 clearcoat. alpha: clearcoat_roughness^2. normal: the lobe's normal in the local
  // shading frame (unit, facing wo's side).
  ClearcoatLobe(float weight, float alpha, ClearcoatEstimator estimator, const glm::vec3& wo, const glm::vec3& normal)
      : weight_(weight),
        alpha_(alpha),
        a2_(alpha * alpha),
        singular_(alpha * alpha <= kGgxSingularAlpha2),
        estimator_(estimator),
        tilted_(normal != glm::vec3(0.0f, 0.0f, 1.0f)),
        frame_(ShadingFrame::from_normal(normal)),
        wo_(tilted_ ? frame_.to_local(wo) : wo),
        g1_wo_(ggx_g1(wo_, kClearcoatShadowingAlpha)) {}

  BxDFFlags flags() const { return singular_ ? BxDFFlags::SpecularReflection : BxDFFlags::GlossyReflection; }
  // Cycles weights the pick by the lobe's Fresnel toward the viewer.
  float sample_weight() const { return weight_ * fresnel_dielectric_cos(std::max(wo_.z, 0.0f), kClearcoatIor); }

  glm::vec3 eval(const glm::vec3& wi_shading, float* pdf) const {
    *pdf = 0.0f;
    const glm::vec3 wi = tilted_ ? frame_.to_local(wi_shading) : wi_shading;
    if (singular_ || wo_.z <= 0.0f || wi.z <= 0.0f) return glm::vec3(0.0f);
    const glm::vec3 m = glm::normalize(wo_ + wi);
    const float d = gtr1_d(m, a2_);
    const float d_over_4cos = d / (4.0f * wo_.z);
    *pdf = estimator_ == ClearcoatEstimator::Cycles34 ? g1_wo_ * d_over_4cos : gtr1_reflection_pdf(wo_, m, a2_);
    const float f_cos = weight_ * fresnel_dielectric_cos(glm::dot(wi, m), kClearcoatIor) * d_over_4cos * g1_wo_ *
                        ggx_g1(wi, kClearcoatShadowingAlpha);
    return glm::vec3(f_cos);
  }

  bool sample(glm::vec2 u, LobeSample* out) const {
    if (wo_.z <= 0.0f) return false;
    glm::vec3 wi;
    if (singular_) {
      wi = glm::vec3(-wo_.x, -wo_.y, wo_.z);
      out->specular_weight = glm::vec3(weight_ * fresnel_dielectric_cos(wo_.z, kClearcoatIor));
    } else {
      const glm::vec3 m = estimator_ == ClearcoatEstimator::Cycles34 ? ggx_sample_visible_normal(wo_, alpha_, u)
                                                                     : gtr1_sample_normal(a2_, u);
      // A normal facing away from wo reflects nothing (GTR1 sampling draws them; visible normals never do).
      if (glm::dot(wo_, m) <= 0.0f) return false;
      wi = reflect_about(wo_, m);
      if (wi.z <= 0.0f) return false;
    }
    out->wi = tilted_ ? frame_.to_world(wi) : wi;
    return true;
  }

 private:
  float weight_ = 0.0f;
  float alpha_ = 0.0f;
  float a2_ = 0.0f;
  bool singular_ = true;
  ClearcoatEstimator estimator_ = ClearcoatEstimator::Integral;
  bool tilted_ = false;  // the lobe's normal is not the shading normal: directions go through frame_
  ShadingFrame frame_{};
  glm::vec3 wo_{0.0f, 0.0f, 1.0f};  // in the lobe's own frame
  float g1_wo_ = 1.0f;
};

}  // namespace matrender
