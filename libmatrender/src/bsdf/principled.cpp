#include "bsdf/principled.h"

#include <algorithm>

#include "bsdf/bump_shadowing.h"
#include "bsdf/microfacet_ggx.h"
#include "bsdf/principled_diffuse.h"

namespace matrender {
namespace {

float average(const glm::vec3& c) { return (c.x + c.y + c.z) / 3.0f; }

// Rec.709 luminance, Cycles' linear_rgb_to_gray for the default scene-linear space.
float luminance(const glm::vec3& c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

}  // namespace

PrincipledBsdf::PrincipledBsdf(const PrincipledInputs& inputs, const glm::vec3& wo, const glm::vec3& smooth_normal)
    : wo_(wo),
      smooth_normal_(smooth_normal),
      bump_shadowing_(smooth_normal != glm::vec3(0.0f, 0.0f, 1.0f)),
      diffuse_model_(inputs.diffuse_model) {
  const glm::vec3 base = glm::max(inputs.base_color, glm::vec3(0.0f));
  const float metallic = glm::clamp(inputs.metallic, 0.0f, 1.0f);
  const float specular = glm::clamp(inputs.specular, 0.0f, 1.0f);
  const float tint_amount = glm::clamp(inputs.specular_tint, 0.0f, 1.0f);
  roughness_ = glm::clamp(inputs.roughness, 0.0f, 1.0f);
  alpha_ = roughness_ * roughness_;
  singular_ = alpha_ * alpha_ <= kGgxSingularAlpha2;

  diffuse_weight_ = (1.0f - metallic) * base;
  specular_enabled_ = specular > 0.0f || metallic > 0.0f;

  // cspec0 = mix(0.08 specular mix(1, tint, specular_tint), base, metallic), tint = base / lum.
  const float lum = luminance(base);
  const glm::vec3 tint = lum > 0.0f ? base / lum : glm::vec3(1.0f);
  const glm::vec3 dielectric = 0.08f * specular * glm::mix(glm::vec3(1.0f), tint, tint_amount);
  fresnel_ = InterpolatedFresnel(glm::mix(dielectric, base, metallic),
                                 principled_specular_ior(specular));

  const float diffuse_sample_weight = average(diffuse_weight_);
  const float specular_sample_weight =
      specular_enabled_ ? average(fresnel_(std::max(wo.z, 0.0f))) : 0.0f;
  const float total = diffuse_sample_weight + specular_sample_weight;
  diffuse_probability_ = total > 0.0f ? diffuse_sample_weight / total : 0.0f;
  if (!(total > 0.0f)) specular_enabled_ = false;
}

glm::vec3 PrincipledBsdf::eval_diffuse(const glm::vec3& wi) const {
  if (diffuse_probability_ <= 0.0f) return glm::vec3(0.0f);
  const float f_cos = diffuse_model_ == DiffuseModel::Principled
                          ? principled_diffuse_eval_cos(wo_, wi, roughness_)
                          : lambert_eval_cos(wo_, wi);
  const float shadowing = bump_shadowing_ ? bump_shadowing_term(smooth_normal_, wi) : 1.0f;
  return diffuse_weight_ * (f_cos * shadowing);
}

glm::vec3 PrincipledBsdf::eval_specular(const glm::vec3& wi) const {
  if (!specular_enabled_ || singular_ || wo_.z <= 0.0f || wi.z <= 0.0f) return glm::vec3(0.0f);
  const glm::vec3 m = glm::normalize(wo_ + wi);
  const float d = ggx_d(m, alpha_);
  const float g = ggx_g1(wo_, alpha_) * ggx_g1(wi, alpha_);
  // f cos = F D G / (4 cos_o cos_i) * cos_i
  return fresnel_(glm::dot(wi, m)) * (d * g / (4.0f * wo_.z));
}

glm::vec3 PrincipledBsdf::eval(const glm::vec3& wi, float* pdf) const {
  float mixture_pdf = 0.0f;
  glm::vec3 value(0.0f);
  if (diffuse_probability_ > 0.0f) {
    value += eval_diffuse(wi);
    mixture_pdf += diffuse_probability_ * diffuse_pdf(wo_, wi);
  }
  if (specular_enabled_ && !singular_) {
    value += eval_specular(wi);
    mixture_pdf += (1.0f - diffuse_probability_) * ggx_reflection_pdf(wo_, wi, alpha_);
  }
  *pdf = mixture_pdf;
  return value;
}

bool PrincipledBsdf::sample(glm::vec2 u, BsdfSample* out) const {
  const float u_lobe = u.x;
  const float p = diffuse_probability_;
  const float rescaled = u_lobe < p ? u_lobe / p : (u_lobe - p) / (1.0f - p);
  u.x = std::min(rescaled, 0x1.fffffep-1f);
  return sample(u_lobe, u, out);
}

bool PrincipledBsdf::sample(float u_lobe, glm::vec2 u, BsdfSample* out) const {
  if (wo_.z <= 0.0f) return false;
  const bool pick_diffuse = u_lobe < diffuse_probability_;
  if (!pick_diffuse && !specular_enabled_) return false;

  if (!pick_diffuse && singular_) {
    out->wi = glm::vec3(-wo_.x, -wo_.y, wo_.z);
    out->weight = fresnel_(wo_.z) / (1.0f - diffuse_probability_);
    out->pdf = 0.0f;
    out->delta = true;
    out->glossy = true;
    return true;
  }

  glm::vec3 wi;
  if (pick_diffuse) {
    wi = diffuse_sample(u);
  } else {
    wi = reflect_about(wo_, ggx_sample_visible_normal(wo_, alpha_, u));
  }
  if (wi.z <= 0.0f) return false;
  float pdf;
  const glm::vec3 value = eval(wi, &pdf);
  if (!(pdf > 0.0f)) return false;
  out->wi = wi;
  out->weight = value / pdf;
  out->pdf = pdf;
  out->delta = false;
  out->glossy = !pick_diffuse;
  return true;
}

}  // namespace matrender
