#pragma once
// The Principled BSDF of Blender 3.4 Cycles restricted to what matpredict's materials use:
// a diffuse lobe weighted (1 - metallic) * base colour plus a GGX specular lobe with the
// interpolated Fresnel, added on top (svm_closure.h, CLOSURE_BSDF_PRINCIPLED_ID). A material
// without a lobe pays nothing for it: specular 0 and metallic 0 make no specular lobe at all.
#include <glm/glm.hpp>

#include "bsdf/fresnel.h"
#include "matrender/material.h"

namespace matrender {

// Material inputs after texture lookups, for one shading point.
struct PrincipledInputs {
  glm::vec3 base_color{0.8f};
  float metallic = 0.0f;
  float roughness = 0.5f;
  float specular = 0.5f;
  float specular_tint = 0.0f;
  DiffuseModel diffuse_model = DiffuseModel::Principled;
};

struct BsdfSample {
  glm::vec3 wi{0.0f};
  glm::vec3 weight{0.0f};  // f cos / pdf (for a delta lobe: its reflectance / selection prob.)
  float pdf = 0.0f;        // solid-angle pdf of the whole mixture; 0 for a delta lobe
  bool delta = false;      // mirror reflection of a singular GGX lobe
  bool glossy = false;     // which lobe was sampled (Cycles' diffuse vs glossy bounce counts)
};

// What the lobes take from the material inputs alone, before any view direction: computed once
// per material when no input is textured, once per shading point otherwise.
struct PrincipledLobes {
  explicit PrincipledLobes(const PrincipledInputs& inputs);

  glm::vec3 diffuse_weight{0.0f};  // (1 - metallic) base colour
  DiffuseModel diffuse_model;
  float roughness;
  float alpha;                     // GGX alpha = roughness^2
  bool singular;                   // a perfect mirror
  bool specular_enabled;           // specular > 0 or metallic > 0
  InterpolatedFresnel fresnel;
};

// All directions in the local shading frame: +Z = shading normal, pointing away from the surface.
class PrincipledBsdf {
 public:
  // smooth_normal: Cycles' sd->N (the interpolated normal before normal mapping and
  // ensure_valid_reflection) in the local frame. Where it differs from +Z, the diffuse lobe is
  // multiplied by Cycles' bump shadowing term (bump_shadowing.h).
  PrincipledBsdf(const PrincipledLobes& lobes, const glm::vec3& wo,
                 const glm::vec3& smooth_normal = glm::vec3(0.0f, 0.0f, 1.0f));
  PrincipledBsdf(const PrincipledInputs& inputs, const glm::vec3& wo,
                 const glm::vec3& smooth_normal = glm::vec3(0.0f, 0.0f, 1.0f))
      : PrincipledBsdf(PrincipledLobes(inputs), wo, smooth_normal) {}

  // Sum over lobes of weight * f * cos(theta_i); *pdf receives the mixture pdf of sampling wi.
  glm::vec3 eval(const glm::vec3& wi, float* pdf) const;

  // Picks a lobe with u_lobe (proportional to the lobe's sample weight, as Cycles does) and a
  // direction with u. Returns false when no direction could be made (no lobe, below horizon).
  bool sample(float u_lobe, glm::vec2 u, BsdfSample* out) const;
  // The same with the lobe picked by u.x, which is then rescaled within the picked lobe's
  // interval and reused for the direction, so each lobe's directions keep u's 2-D
  // stratification (Cycles 3.4, kernel/closure/... shader_bsdf_pick: "rescale to reuse for
  // direction sample").
  bool sample(glm::vec2 u, BsdfSample* out) const;

  bool has_diffuse() const { return diffuse_probability_ > 0.0f; }
  bool has_specular() const { return diffuse_probability_ < 1.0f && specular_enabled_; }
  // True when every lobe is a delta (light sampling cannot contribute).
  bool is_delta_only() const { return !has_diffuse() && lobes_.singular; }

  // Weight * f * cos of the lobes separately, for tests against the reference.
  glm::vec3 eval_diffuse(const glm::vec3& wi) const;
  glm::vec3 eval_specular(const glm::vec3& wi) const;

 private:
  // The specular value and, in *pdf, the specular lobe's own sampling pdf.
  glm::vec3 eval_specular(const glm::vec3& wi, float* pdf) const;

  PrincipledLobes lobes_;
  glm::vec3 wo_;
  glm::vec3 smooth_normal_;
  bool bump_shadowing_;     // smooth_normal_ differs from the shading normal
  bool specular_enabled_;   // the lobes' flag, off when neither lobe reflects anything from wo
  float g1_wo_over_4cos_;   // Smith G1(wo) / (4 cos_o), shared by every evaluation
  float diffuse_probability_ = 0.0f;  // 1 - specular probability; 0 when there is no diffuse lobe
};

}  // namespace matrender
