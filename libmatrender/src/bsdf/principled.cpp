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

PrincipledLobes::PrincipledLobes(const PrincipledInputs& inputs) : diffuse_model(inputs.diffuse_model) {
  const glm::vec3 base = glm::max(inputs.base_color, glm::vec3(0.0f));
  const float metallic = glm::clamp(inputs.metallic, 0.0f, 1.0f);
  const float specular = glm::clamp(inputs.specular, 0.0f, 1.0f);
  const float tint_amount = glm::clamp(inputs.specular_tint, 0.0f, 1.0f);
  roughness = glm::clamp(inputs.roughness, 0.0f, 1.0f);
  alpha = roughness * roughness;
  singular = alpha * alpha <= kGgxSingularAlpha2;

  diffuse_weight = (1.0f - metallic) * base;
  specular_enabled = specular > 0.0f || metallic > 0.0f;

  // cspec0 = mix(0.08 specular mix(1, tint, specular_tint), base, metallic), tint = base / lum.
  const float lum = luminance(base);
  const glm::vec3 tint = lum > 0.0f ? base / lum : glm::vec3(1.0f);
  const glm::vec3 dielectric = 0.08f * specular * glm::mix(glm::vec3(1.0f), tint, tint_amount);
  // principled_specular_ior makes ((ior - 1) / (ior + 1))^2 = 0.08 specular: F(1) needs no evaluation.
  fresnel = InterpolatedFresnel(glm::mix(dielectric, base, metallic), principled_specular_ior(specular),
                                0.08f * specular);
}

PrincipledBsdf::PrincipledBsdf(const PrincipledLobes& lobes, const glm::vec3& wo, const glm::vec3& smooth_normal)
    : lobes_(lobes),
      wo_(wo),
      smooth_normal_(smooth_normal),
      bump_shadowing_(smooth_normal != glm::vec3(0.0f, 0.0f, 1.0f)),
      specular_enabled_(lobes.specular_enabled) {
  const float diffuse_sample_weight = average(lobes_.diffuse_weight);
  const float specular_sample_weight =
      specular_enabled_ ? average(lobes_.fresnel(std::max(wo.z, 0.0f))) : 0.0f;
  const float total = diffuse_sample_weight + specular_sample_weight;
  diffuse_probability_ = total > 0.0f ? diffuse_sample_weight / total : 0.0f;
  if (!(total > 0.0f)) specular_enabled_ = false;
  g1_wo_over_4cos_ = specular_enabled_ && !lobes_.singular ? ggx_g1(wo, lobes_.alpha) / (4.0f * wo.z) : 0.0f;
}

glm::vec3 PrincipledBsdf::eval_diffuse(const glm::vec3& wi) const {
  if (diffuse_probability_ <= 0.0f) return glm::vec3(0.0f);
  const float f_cos = lobes_.diffuse_model == DiffuseModel::Principled
                          ? principled_diffuse_eval_cos(wo_, wi, lobes_.roughness)
                          : lambert_eval_cos(wo_, wi);
  const float shadowing = bump_shadowing_ ? bump_shadowing_term(smooth_normal_, wi) : 1.0f;
  return lobes_.diffuse_weight * (f_cos * shadowing);
}

glm::vec3 PrincipledBsdf::eval_specular(const glm::vec3& wi) const {
  float unused_pdf;
  return eval_specular(wi, &unused_pdf);
}

glm::vec3 PrincipledBsdf::eval_specular(const glm::vec3& wi, float* pdf) const {
  *pdf = 0.0f;
  if (!specular_enabled_ || lobes_.singular || wo_.z <= 0.0f || wi.z <= 0.0f) return glm::vec3(0.0f);
  const glm::vec3 m = glm::normalize(wo_ + wi);
  // D G1(wo) / (4 cos_o) is both the visible-normal sampling pdf of wi (ggx_reflection_pdf) and,
  // times F G1(wi), the value f cos = F D G / (4 cos_o cos_i) * cos_i.
  const float d_g1_over_4cos = ggx_d(m, lobes_.alpha) * g1_wo_over_4cos_;
  *pdf = d_g1_over_4cos;
  return lobes_.fresnel(glm::dot(wi, m)) * (d_g1_over_4cos * ggx_g1(wi, lobes_.alpha));
}

glm::vec3 PrincipledBsdf::eval(const glm::vec3& wi, float* pdf) const {
  float mixture_pdf = 0.0f;
  glm::vec3 value(0.0f);
  if (diffuse_probability_ > 0.0f) {
    value += eval_diffuse(wi);
    mixture_pdf += diffuse_probability_ * diffuse_pdf(wo_, wi);
  }
  if (specular_enabled_ && !lobes_.singular) {
    float specular_pdf;
    value += eval_specular(wi, &specular_pdf);
    mixture_pdf += (1.0f - diffuse_probability_) * specular_pdf;
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

  if (!pick_diffuse && lobes_.singular) {
    out->wi = glm::vec3(-wo_.x, -wo_.y, wo_.z);
    out->weight = lobes_.fresnel(wo_.z) / (1.0f - diffuse_probability_);
    out->pdf = 0.0f;
    out->delta = true;
    out->glossy = true;
    return true;
  }

  glm::vec3 wi;
  if (pick_diffuse) {
    wi = diffuse_sample(u);
  } else {
    wi = reflect_about(wo_, ggx_sample_visible_normal(wo_, lobes_.alpha, u));
  }
  if (wi.z <= 0.0f) return false;
  float pdf;
  const glm::vec3 value = eval(wi, &pdf);
  if (!(pdf > 0.0f)) return false;
  out->wi = wi;
  out->weight = value * (1.0f / pdf);
  out->pdf = pdf;
  out->delta = false;
  out->glossy = !pick_diffuse;
  return true;
}

}  // namespace matrender
