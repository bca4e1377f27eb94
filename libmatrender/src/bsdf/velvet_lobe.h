#pragma once
// Cycles 3.4's Velvet BSDF (kernel/closure/bsdf_ashikhmin_velvet.h), which Blender's glTF importer
// adds to the Principled BSDF for KHR_materials_sheen. Ashikhmin, Premoze and Shirley's cloth
// model (2000) in Cook-Torrance form, f = D G / (4 cos_i cos_o), with the "inverted" Gaussian
// of the half vector h and the V-groove shadowing of Cook and Torrance (1982, eq. 4):
//   D = exp(-cot^2(theta_h) / sigma^2) / (pi sigma^2 sin^4(theta_h)),
//   G = min(1, 2 cos_h cos_o / (wo.h), 2 cos_h cos_i / (wo.h)),
// sigma = max(Sigma, 0.01). D grows toward grazing half vectors, so the lobe lights the rims of
// cloth. Cycles samples it uniformly over the hemisphere and labels it diffuse. Its normal is the
// node's unlinked Normal input, the smooth normal made valid for reflection, which a normal map
// tilts against the shading frame.
#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "bsdf/bxdf_flags.h"
#include "bsdf/lobe_sample.h"
#include "bsdf/shading_frame.h"
#include "sampling/warp.h"
#include "util/channel_average.h"

namespace matrender {

// bsdf_ashikhmin_velvet_setup: "sigma = fmaxf(sigma, 0.01f)".
constexpr float kVelvetMinSigma = 0.01f;

class VelvetLobe {
 public:
  VelvetLobe() = default;
  // weight: the Velvet BSDF's Color. sigma: its Sigma in [0, 1]. normal: the lobe's normal in the
  // local shading frame (unit, facing wo's side).
  VelvetLobe(const glm::vec3& weight, float sigma, const glm::vec3& wo, const glm::vec3& normal)
      : weight_(weight),
        inv_sigma2_(1.0f / (std::max(sigma, kVelvetMinSigma) * std::max(sigma, kVelvetMinSigma))),
        tilted_(normal != glm::vec3(0.0f, 0.0f, 1.0f)),
        frame_(ShadingFrame::from_normal(normal)),
        wo_(wo),
        cos_o_(glm::dot(normal, wo)) {}

  static constexpr BxDFFlags flags() { return BxDFFlags::DiffuseReflection; }
  // Cycles' closure sample weight, the colour's average; nothing to pick when seen from below.
  float sample_weight() const { return cos_o_ > 0.0f ? channel_average(weight_) : 0.0f; }

  glm::vec3 eval(const glm::vec3& wi, float* pdf) const {
    *pdf = 0.0f;
    const float cos_i = glm::dot(frame_.z, wi);
    if (cos_o_ <= 0.0f || cos_i <= 0.0f) return glm::vec3(0.0f);
    *pdf = kUniformHemispherePdf;
    // Both directions above the lobe's plane: wi + wo has length.
    const glm::vec3 h = glm::normalize(wi + wo_);
    const float cos_h = glm::dot(frame_.z, h);
    const float cos_hi = std::abs(glm::dot(wi, h));
    // Cycles' guards: no half vector at the normal (cot^2 without bound), none across the lobe.
    if (!(std::abs(cos_h) < 1.0f - 1e-5f && cos_hi > 1e-5f)) return glm::vec3(0.0f);
    const float cos_h_over_hi = std::max(cos_h / cos_hi, 1e-5f);
    const float shadowing = std::min({1.0f, 2.0f * cos_h_over_hi * cos_i, 2.0f * cos_h_over_hi * cos_o_});
    const float sin2_h = 1.0f - cos_h * cos_h;
    const float distribution =
        std::exp(-(cos_h * cos_h / sin2_h) * inv_sigma2_) * inv_sigma2_ * kInvPi / (sin2_h * sin2_h);
    // f cos_i = D G / (4 cos_o).
    return weight_ * (0.25f * distribution * shadowing / cos_o_);
  }

  bool sample(glm::vec2 u, LobeSample* out) const {
    if (cos_o_ <= 0.0f) return false;
    const glm::vec3 local = sample_uniform_hemisphere(u);
    if (!(local.z > 0.0f)) return false;
    out->wi = tilted_ ? frame_.to_world(local) : local;
    return true;
  }

 private:
  glm::vec3 weight_{0.0f};
  float inv_sigma2_ = 1.0f;
  bool tilted_ = false;  // the lobe's normal is not the shading normal: samples go through frame_
  ShadingFrame frame_{ShadingFrame::from_normal(glm::vec3(0.0f, 0.0f, 1.0f))};  // z: the lobe's normal
  glm::vec3 wo_{0.0f, 0.0f, 1.0f};
  float cos_o_ = 1.0f;
};

}  // namespace matrender
