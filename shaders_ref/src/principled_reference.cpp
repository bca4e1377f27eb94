#include "shaders_ref/principled_reference.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "matbase/pi.h"

namespace shaders_ref {
namespace {

using matbase::kPi;

// Cycles makes no closure whose average weight is below 1e-5 (CLOSURE_WEIGHT_CUTOFF).
constexpr double kClosureWeightCutoff = 1e-5;

// Schlick's weight (1 - cos)^5 for a cosine in [0, 1].
double fifth_power_of_complement(double cos_theta) {
  const double m = 1.0 - std::clamp(cos_theta, 0.0, 1.0);
  return m * m * m * m * m;
}

}  // namespace

double ggx_alpha(double roughness) { return roughness * roughness; }

double tan2_theta(const glm::dvec3& w) {
  // sin^2 from the tangential components, so that directions near the normal keep their
  // relative precision (1 - cos^2 would cancel).
  const double sin2 = w.x * w.x + w.y * w.y;
  const double cos2 = w.z * w.z;
  if (cos2 == 0.0) return std::numeric_limits<double>::infinity();
  return sin2 / cos2;
}

double ggx_ndf(const glm::dvec3& m, double alpha) {
  if (m.z <= 0.0) return 0.0;
  const double cos2 = m.z * m.z;
  const double a2 = alpha * alpha;
  const double slope_term = 1.0 + tan2_theta(m) / a2;
  return 1.0 / (kPi * a2 * cos2 * cos2 * slope_term * slope_term);
}

double ggx_lambda(const glm::dvec3& w, double alpha) {
  const double t2 = tan2_theta(w);
  if (std::isinf(t2)) return std::numeric_limits<double>::infinity();
  return 0.5 * (std::sqrt(1.0 + alpha * alpha * t2) - 1.0);
}

double ggx_smith_g1(const glm::dvec3& w, double alpha) {
  if (w.z <= 0.0) return 0.0;
  return 1.0 / (1.0 + ggx_lambda(w, alpha));
}

double dielectric_fresnel(double cos_i, double eta) {
  const double ci = std::min(std::abs(cos_i), 1.0);
  const double sin2_i = 1.0 - ci * ci;
  const double sin2_t = sin2_i / (eta * eta);  // Snell: sin_t = sin_i / eta
  if (sin2_t >= 1.0) return 1.0;
  const double ct = std::sqrt(1.0 - sin2_t);
  const double r_s = (ci - eta * ct) / (ci + eta * ct);
  const double r_p = (eta * ci - ct) / (eta * ci + ct);
  return 0.5 * (r_s * r_s + r_p * r_p);
}

double principled_specular_ior(double specular) {
  return 2.0 / (1.0 - std::sqrt(0.08 * specular)) - 1.0;
}

double rec709_luminance(const glm::dvec3& rgb) {
  return 0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b;
}

glm::dvec3 specular_color_at_normal_incidence(const PrincipledParams& p) {
  const double lum = rec709_luminance(p.base_color);
  const glm::dvec3 tint = lum > 0.0 ? p.base_color / lum : glm::dvec3(1.0);
  const glm::dvec3 dielectric =
      0.08 * p.specular * ((1.0 - p.specular_tint) * glm::dvec3(1.0) + p.specular_tint * tint);
  return (1.0 - p.metallic) * dielectric + p.metallic * p.base_color;
}

glm::dvec3 interpolated_fresnel(const PrincipledParams& p, double cos_i) {
  const double ior = principled_specular_ior(p.specular);
  const double f_normal = dielectric_fresnel(1.0, ior);
  const double fh = (dielectric_fresnel(cos_i, ior) - f_normal) / (1.0 - f_normal);
  return specular_color_at_normal_incidence(p) * (1.0 - fh) + glm::dvec3(fh);
}

bool has_specular_lobe(const PrincipledParams& p) { return p.specular > 0.0 || p.metallic > 0.0; }

glm::dvec3 diffuse_brdf(const PrincipledParams& p, const glm::dvec3& wo, const glm::dvec3& wi) {
  if (wo.z <= 0.0 || wi.z <= 0.0) return glm::dvec3(0.0);
  const glm::dvec3 weight = (1.0 - p.metallic) * (1.0 - p.transmission) * p.base_color;
  if (p.lambert_diffuse) return weight / kPi;
  const double fl = fifth_power_of_complement(wi.z);
  const double fv = fifth_power_of_complement(wo.z);
  const double rr = p.roughness * (1.0 + glm::dot(wi, wo));
  const double lambert_part = (1.0 - 0.5 * fv) * (1.0 - 0.5 * fl);
  const double retro_reflection = rr * (fl + fv + fl * fv * (rr - 1.0));
  return weight * ((lambert_part + retro_reflection) / kPi);
}

glm::dvec3 sheen_brdf(const PrincipledParams& p, const glm::dvec3& wo, const glm::dvec3& wi) {
  if (wo.z <= 0.0 || wi.z <= 0.0) return glm::dvec3(0.0);
  const double lum = rec709_luminance(p.base_color);
  const glm::dvec3 tint = lum > 0.0 ? p.base_color / lum : glm::dvec3(1.0);
  const glm::dvec3 colour = (1.0 - p.sheen_tint) * glm::dvec3(1.0) + p.sheen_tint * tint;
  const glm::dvec3 h = glm::normalize(wo + wi);
  return p.sheen * (1.0 - p.metallic) * (1.0 - p.transmission) * colour * fifth_power_of_complement(glm::dot(wi, h));
}

glm::dvec3 velvet_brdf(const PrincipledParams& p, const glm::dvec3& wo, const glm::dvec3& wi) {
  const glm::dvec3 colour = glm::max(p.velvet_color, glm::dvec3(0.0));
  if ((colour.x + colour.y + colour.z) / 3.0 < kClosureWeightCutoff || wo.z <= 0.0 || wi.z <= 0.0)
    return glm::dvec3(0.0);
  const double s = std::clamp(p.velvet_sigma, 0.01, 1.0);
  const glm::dvec3 h = glm::normalize(wo + wi);
  const double sin2_h = h.x * h.x + h.y * h.y;
  if (sin2_h == 0.0) return glm::dvec3(0.0);  // cot^2 infinite: D vanishes
  const double cot2_h = h.z * h.z / sin2_h;
  const double d = std::exp(-cot2_h / (s * s)) / (kPi * s * s * sin2_h * sin2_h);
  const double wo_dot_h = glm::dot(wo, h);
  const double g = std::min({1.0, 2.0 * h.z * wo.z / wo_dot_h, 2.0 * h.z * wi.z / wo_dot_h});
  return colour * (d * g / (4.0 * wo.z * wi.z));
}

glm::dvec3 specular_brdf(const PrincipledParams& p, const glm::dvec3& wo, const glm::dvec3& wi) {
  if (!has_specular_lobe(p) || wo.z <= 0.0 || wi.z <= 0.0) return glm::dvec3(0.0);
  const double alpha = ggx_alpha(p.roughness);
  const glm::dvec3 h = glm::normalize(wo + wi);
  const double shadowing = ggx_smith_g1(wo, alpha) * ggx_smith_g1(wi, alpha);
  const double specular_weight = 1.0 - p.transmission * (1.0 - p.metallic);
  return specular_weight * interpolated_fresnel(p, glm::dot(wi, h)) *
         (ggx_ndf(h, alpha) * shadowing / (4.0 * wo.z * wi.z));
}

double glass_eta(const PrincipledParams& p) { return p.front_face ? p.ior : 1.0 / p.ior; }

glm::dvec3 glass_reflection_brdf(const PrincipledParams& p, const glm::dvec3& wo, const glm::dvec3& wi) {
  if (p.transmission <= 0.0 || wo.z <= 0.0 || wi.z <= 0.0) return glm::dvec3(0.0);
  const double eta = glass_eta(p);
  const double alpha = ggx_alpha(p.roughness);
  const glm::dvec3 h = glm::normalize(wo + wi);
  const glm::dvec3 cspec0 = (1.0 - p.specular_tint) * glm::dvec3(1.0) + p.specular_tint * p.base_color;
  const double f_normal = dielectric_fresnel(1.0, eta);
  const double fh = (dielectric_fresnel(glm::dot(wi, h), eta) - f_normal) / (1.0 - f_normal);
  const glm::dvec3 fresnel = cspec0 * (1.0 - fh) + glm::dvec3(fh);
  const double weight = p.transmission * (1.0 - p.metallic) * dielectric_fresnel(wo.z, eta);
  if (weight < kClosureWeightCutoff) return glm::dvec3(0.0);
  const double shadowing = ggx_smith_g1(wo, alpha) * ggx_smith_g1(wi, alpha);
  return weight * fresnel * (ggx_ndf(h, alpha) * shadowing / (4.0 * wo.z * wi.z));
}

glm::dvec3 glass_refraction_btdf(const PrincipledParams& p, const glm::dvec3& wo, const glm::dvec3& wi) {
  if (p.transmission <= 0.0 || wo.z <= 0.0 || wi.z >= 0.0) return glm::dvec3(0.0);
  const double eta = glass_eta(p);
  const double roughness = 1.0 - (1.0 - p.roughness) * (1.0 - p.transmission_roughness);
  const double alpha = ggx_alpha(roughness);
  glm::dvec3 h = -(wo + eta * wi);
  if (glm::length(h) == 0.0) return glm::dvec3(0.0);
  h = glm::normalize(h.z < 0.0 ? -h : h);
  const double wo_h = glm::dot(wo, h), wi_h = glm::dot(wi, h);
  if (wo_h <= 0.0 || wi_h >= 0.0) return glm::dvec3(0.0);
  const glm::dvec3 below(wi.x, wi.y, -wi.z);  // G1 of the transmitted direction, seen from its side
  const double shadowing = ggx_smith_g1(wo, alpha) * ggx_smith_g1(below, alpha);
  const double denominator = wo_h + eta * wi_h;
  const double btdf = std::abs(wi_h) * wo_h * eta * eta * ggx_ndf(h, alpha) * shadowing /
                      (wo.z * std::abs(wi.z) * denominator * denominator);
  const glm::dvec3 weight =
      p.transmission * (1.0 - p.metallic) * std::max(1e-4, 1.0 - dielectric_fresnel(wo.z, eta)) * p.base_color;
  if ((weight.x + weight.y + weight.z) / 3.0 < kClosureWeightCutoff) return glm::dvec3(0.0);
  return weight * btdf;
}

double gtr1_ndf(const glm::dvec3& m, double a) {
  if (m.z <= 0.0) return 0.0;
  if (a >= 1.0) return 1.0 / kPi;
  const double a2 = a * a;
  return (a2 - 1.0) / (kPi * std::log(a2) * (1.0 + (a2 - 1.0) * m.z * m.z));
}

glm::dvec3 clearcoat_brdf(const PrincipledParams& p, const glm::dvec3& wo, const glm::dvec3& wi) {
  if (p.clearcoat <= 0.0 || wo.z <= 0.0 || wi.z <= 0.0) return glm::dvec3(0.0);
  constexpr double kShadowingAlpha = 0.25;
  const glm::dvec3 h = glm::normalize(wo + wi);
  const double shadowing = ggx_smith_g1(wo, kShadowingAlpha) * ggx_smith_g1(wi, kShadowingAlpha);
  const double f = 0.25 * p.clearcoat * dielectric_fresnel(glm::dot(wi, h), 1.5) *
                   gtr1_ndf(h, ggx_alpha(p.clearcoat_roughness)) * shadowing / (4.0 * wo.z * wi.z);
  return glm::dvec3(f);
}

glm::dvec3 principled_brdf(const PrincipledParams& p, const glm::dvec3& wo, const glm::dvec3& wi) {
  return diffuse_brdf(p, wo, wi) + sheen_brdf(p, wo, wi) + specular_brdf(p, wo, wi) + clearcoat_brdf(p, wo, wi) +
         glass_reflection_brdf(p, wo, wi) + velvet_brdf(p, wo, wi);
}

}  // namespace shaders_ref
