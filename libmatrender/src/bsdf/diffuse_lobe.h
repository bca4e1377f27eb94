#pragma once
// The diffuse lobe of the Principled BSDF (principled_diffuse.h): principled diffuse with
// retro-reflection or plain Lambert, cosine-sampled, with Cycles' bump shadowing term where the
// shading normal differs from the smooth normal.
#include <glm/glm.hpp>

#include "bsdf/bump_shadowing.h"
#include "bsdf/bxdf_flags.h"
#include "bsdf/lobe_sample.h"
#include "bsdf/principled_diffuse.h"
#include "matrender/material.h"
#include "util/channel_average.h"

namespace matrender {

class DiffuseLobe {
 public:
  DiffuseLobe() = default;
  // weight: the closure weight, (1 - metallic) base colour. smooth_normal: Cycles' sd->N in the
  // local frame (bump_shadowing.h); +Z when there is no normal map and no bent normal.
  DiffuseLobe(const glm::vec3& weight, DiffuseModel model, float roughness, const glm::vec3& wo,
              const glm::vec3& smooth_normal)
      : weight_(weight),
        model_(model),
        roughness_(roughness),
        wo_(wo),
        smooth_normal_(smooth_normal),
        bump_shadowing_(smooth_normal != glm::vec3(0.0f, 0.0f, 1.0f)) {}

  static constexpr BxDFFlags flags() { return BxDFFlags::DiffuseReflection; }
  float sample_weight() const { return channel_average(weight_); }

  glm::vec3 eval(const glm::vec3& wi, float* pdf) const {
    *pdf = diffuse_pdf(wo_, wi);
    const float f_cos = model_ == DiffuseModel::Principled ? principled_diffuse_eval_cos(wo_, wi, roughness_)
                                                           : lambert_eval_cos(wo_, wi);
    const float shadowing = bump_shadowing_ ? bump_shadowing_term(smooth_normal_, wi) : 1.0f;
    return weight_ * (f_cos * shadowing);
  }

  bool sample(glm::vec2 u, LobeSample* out) const { return sample_diffuse_lobe(wo_, u, out); }

 private:
  glm::vec3 weight_{0.0f};
  DiffuseModel model_ = DiffuseModel::Principled;
  float roughness_ = 0.0f;
  glm::vec3 wo_{0.0f, 0.0f, 1.0f};
  glm::vec3 smooth_normal_{0.0f, 0.0f, 1.0f};
  bool bump_shadowing_ = false;
};

}  // namespace matrender
