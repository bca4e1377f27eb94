#pragma once
// Fresnel terms of Cycles 3.4's Principled BSDF (intern/cycles/kernel/closure/bsdf_util.h:
// fresnel_dielectric_cos; bsdf_microfacet.h: interpolate_fresnel_color).
#include <cmath>

#include <glm/glm.hpp>

namespace matrender {

// Unpolarised Fresnel reflectance of a dielectric interface with relative index `eta`, for
// cos_i = cosine between the incident direction and the (micro)normal. Total internal
// reflection returns 1.
inline float fresnel_dielectric_cos(float cos_i, float eta) {
  const float c = std::abs(cos_i);
  const float g2 = eta * eta - 1.0f + c * c;
  if (g2 <= 0.0f) return 1.0f;
  const float g = std::sqrt(g2);
  const float a = (g - c) / (g + c);
  const float b = (c * (g + c) - 1.0f) / (c * (g - c) + 1.0f);
  return 0.5f * a * a * (1.0f + b * b);
}

// The Principled BSDF's ior from its "specular" input: 0.08 * specular = F0 = ((ior-1)/(ior+1))^2.
inline float principled_specular_ior(float specular) {
  return 2.0f / (1.0f - std::sqrt(std::max(0.0f, 0.08f * specular))) - 1.0f;
}

// Cycles' "interpolated" Fresnel: the dielectric curve renormalised to run from cspec0 at
// normal incidence to 1 at grazing: FH = (F(cos, ior) - F0) / (1 - F0), F = mix(cspec0, 1, FH).
struct InterpolatedFresnel {
  glm::vec3 cspec0{0.04f};
  float ior = 1.5f;
  float f0 = 0.04f;  // fresnel_dielectric_cos(1, ior)
  float inv_one_minus_f0 = 1.0f / 0.96f;  // once per material, not one division per evaluation

  InterpolatedFresnel() = default;
  InterpolatedFresnel(glm::vec3 cspec0_, float ior_) : InterpolatedFresnel(cspec0_, ior_, fresnel_dielectric_cos(1.0f, ior_)) {}
  // With f0 = fresnel_dielectric_cos(1, ior) known: ((ior - 1) / (ior + 1))^2 in closed form.
  InterpolatedFresnel(glm::vec3 cspec0_, float ior_, float f0_)
      : cspec0(cspec0_), ior(ior_), f0(f0_), inv_one_minus_f0(1.0f / (1.0f - f0_)) {}

  glm::vec3 operator()(float cos_i) const {
    const float fh = (fresnel_dielectric_cos(cos_i, ior) - f0) * inv_one_minus_f0;
    return cspec0 * (1.0f - fh) + glm::vec3(fh);
  }
};

}  // namespace matrender
