#pragma once
// Reference Principled BSDF v1 of Blender 3.4 Cycles (principled or Lambert diffuse, sheen, a
// single-scatter GGX specular lobe with the "interpolated" Fresnel, clearcoat, glass), and the
// Velvet BSDF that Blender's glTF importer adds beside it for glTF's sheen, written plainly in double
// precision from the published equations. It shares no code with libmatrender: it is the
// independent implementation the fast float code is tested against (docs/conventions.md,
// "Principled BSDF v1").
//
// Local frame: +Z is the shading normal; wo (towards the viewer) and wi (towards the light) are
// unit vectors pointing away from the surface. Every *_brdf function returns the BRDF value f
// itself, without the cos(theta_i) factor of the rendering equation.
#include <glm/glm.hpp>

namespace shaders_ref {

struct PrincipledParams {
  glm::dvec3 base_color{0.8};
  double metallic = 0.0;
  double roughness = 0.5;
  double specular = 0.5;
  double specular_tint = 0.0;
  double sheen = 0.0;
  double sheen_tint = 0.5;
  double clearcoat = 0.0;
  double clearcoat_roughness = 0.03;
  double transmission = 0.0;
  double transmission_roughness = 0.0;
  double ior = 1.45;
  glm::dvec3 velvet_color{0.0};  // the Velvet BSDF added to the Principled one (black: none)
  double velvet_sigma = 1.0;
  bool front_face = true;        // the viewer is outside: glass is entered with eta = ior, left with 1 / ior
  bool lambert_diffuse = false;  // Cycles' Diffuse BSDF (f = 1/pi) instead of the principled one
};

// --- GGX (Trowbridge-Reitz) microfacet model -----------------------------------------------

// Cycles' Principled BSDF maps roughness to the GGX width alpha = roughness^2.
double ggx_alpha(double roughness);

// tan^2 of the angle between the unit vector w and +Z; infinite for w in the tangent plane.
double tan2_theta(const glm::dvec3& w);

// Normal distribution D(m) = 1 / (pi alpha^2 cos^4(theta_m) (1 + tan^2(theta_m) / alpha^2)^2),
// zero for m below the tangent plane (Walter et al. 2007, eq. 33).
double ggx_ndf(const glm::dvec3& m, double alpha);

// Smith's auxiliary function Lambda(w) = (sqrt(1 + alpha^2 tan^2(theta)) - 1) / 2
// (Heitz 2014, "Understanding the Masking-Shadowing Function", eq. 72).
double ggx_lambda(const glm::dvec3& w, double alpha);

// Smith masking G1(w) = 1 / (1 + Lambda(w)) for w above the surface, else 0 (Heitz 2014, eq. 43,
// with the microfacet-side factor chi(w.m) > 0 left to the caller).
double ggx_smith_g1(const glm::dvec3& w, double alpha);

// --- Fresnel ---------------------------------------------------------------------------------

// Unpolarised reflectance of a smooth dielectric interface with relative index eta (transmitted
// over incident side) for the incidence cosine cos_i, as the mean of the squared s- and
// p-polarised amplitude coefficients r_s = (cos_i - eta cos_t) / (cos_i + eta cos_t),
// r_p = (eta cos_i - cos_t) / (eta cos_i + cos_t) (Born & Wolf, sec. 1.5.2). Total internal
// reflection gives 1.
double dielectric_fresnel(double cos_i, double eta);

// The specular input's index of refraction: 0.08 specular = ((ior - 1) / (ior + 1))^2, solved as
// ior = 2 / (1 - sqrt(0.08 specular)) - 1.
double principled_specular_ior(double specular);

// Luminance of a scene-linear Rec.709 colour with the luma coefficients of ITU-R BT.709
// (item 3.2): Y = 0.2126 R + 0.7152 G + 0.0722 B.
double rec709_luminance(const glm::dvec3& rgb);

// cspec0 = mix(0.08 specular mix(1, tint, specular_tint), base, metallic) with
// tint = base / luminance(base) (white for a black base).
glm::dvec3 specular_color_at_normal_incidence(const PrincipledParams& p);

// Cycles' interpolated Fresnel: FH = (F(cos_i, ior) - F(1, ior)) / (1 - F(1, ior)),
// F = cspec0 (1 - FH) + FH, with cos_i the cosine between the light direction and the microfacet
// normal.
glm::dvec3 interpolated_fresnel(const PrincipledParams& p, double cos_i);

// --- Lobes -------------------------------------------------------------------------------------

// Specular 0 and metallic 0 make no specular closure at all.
bool has_specular_lobe(const PrincipledParams& p);

// (1 - metallic)(1 - transmission) base times the principled diffuse
// 1/pi [(1 - FV/2)(1 - FL/2) + RR (FL + FV + FL FV (RR - 1))], FL = (1 - cos_i)^5,
// FV = (1 - cos_o)^5, RR = roughness (1 + wi.wo); or times 1/pi for the Lambert lobe.
glm::dvec3 diffuse_brdf(const PrincipledParams& p, const glm::dvec3& wo, const glm::dvec3& wi);

// Burley's sheen (Physically Based Shading at Disney, 2012, sec. 5.3) as Cycles 3.4 scales it:
// sheen (1 - metallic)(1 - transmission) mix(1, tint, sheen_tint) (1 - wi.h)^5 with h = normalize(wo + wi) and
// the tint of specular_color_at_normal_incidence; no 1/pi. Zero below the surface.
glm::dvec3 sheen_brdf(const PrincipledParams& p, const glm::dvec3& wo, const glm::dvec3& wi);

// (1 - transmission (1 - metallic)) F(wi.h) D(h) G1(wo) G1(wi) / (4 cos_o cos_i) with
// h = normalize(wo + wi) (Walter et al. 2007, eq. 20); zero when there is no specular lobe or
// either direction is below the surface. Needs roughness > 0: the reference has no singular
// (mirror) case.
glm::dvec3 specular_brdf(const PrincipledParams& p, const glm::dvec3& wo, const glm::dvec3& wi);

// Berry's distribution ("GTR1", Burley 2012, "Physically Based Shading at Disney", appendix B.2,
// eq. 4) of width a: D(m) = (a^2 - 1) / (pi ln(a^2) (1 + (a^2 - 1) cos^2(theta_m))), 1/pi at a = 1,
// zero below the tangent plane. Normalised: the integral of D(m) cos(theta_m) dm is 1.
double gtr1_ndf(const glm::dvec3& m, double a);

// Cycles 3.4's clearcoat lobe: 0.25 clearcoat F(wi.h; ior 1.5) D_GTR1(h; clearcoat_roughness^2)
// G1(wo) G1(wi) / (4 cos_o cos_i) with Smith-GGX G1 of a fixed alpha 0.25; zero when clearcoat
// is 0 or either direction is below the surface. Needs clearcoat_roughness > 0.
glm::dvec3 clearcoat_brdf(const PrincipledParams& p, const glm::dvec3& wo, const glm::dvec3& wi);

// The relative index of refraction across the surface seen from the viewer: ior entering, 1 / ior leaving.
double glass_eta(const PrincipledParams& p);

// Cycles 3.4's glass reflection: transmission (1 - metallic) F_d(cos_o; eta) times a GGX
// reflection whose Fresnel is interpolated from cspec0 = mix(1, base, specular_tint) at
// normal incidence (interpolated_fresnel's formula with that cspec0 and eta). Needs roughness > 0.
// Zero where the closure's weight is below Cycles' cutoff 1e-5 (it is then not made), as for
// the refraction.
glm::dvec3 glass_reflection_brdf(const PrincipledParams& p, const glm::dvec3& wo, const glm::dvec3& wi);

// Cycles 3.4's glass refraction, wi below the surface: transmission (1 - metallic) base
// max(1e-4, 1 - F_d(cos_o; eta)) times Walter et al.'s rough dielectric BTDF without its Fresnel
// factor (2007, eq. 21; eta_i = 1, eta_o = eta):
//   |wi.h| |wo.h| eta^2 D(h) G1(wo) G1(wi) / (|cos_o| |cos_i| (wo.h + eta wi.h)^2),
// h = -(wo + eta wi) normalised toward +Z (eq. 16), zero unless wo.h > 0 > wi.h, GGX of alpha
// (1 - (1 - roughness)(1 - transmission_roughness))^2. Needs that alpha > 0.
glm::dvec3 glass_refraction_btdf(const PrincipledParams& p, const glm::dvec3& wo, const glm::dvec3& wi);

// Cycles 3.4's Velvet BSDF of colour velvet_color: Ashikhmin, Premoze and Shirley's cloth
// distribution (2000) in a Cook-Torrance microfacet BRDF (Cook & Torrance 1982, eq. 4 for the
// shadowing), f = D(h) G / (4 cos_o cos_i) with h = normalize(wo + wi),
//   D(h) = exp(-cot^2(theta_h) / s^2) / (pi s^2 sin^4(theta_h)),   s = clamp(velvet_sigma, 0.01, 1),
//   G = min(1, 2 cos_h cos_o / (wo.h), 2 cos_h cos_i / (wo.h)).
// Zero below the surface and where the colour's average is below Cycles' cutoff.
glm::dvec3 velvet_brdf(const PrincipledParams& p, const glm::dvec3& wo, const glm::dvec3& wi);

// diffuse_brdf + sheen_brdf + specular_brdf + clearcoat_brdf + glass_reflection_brdf, the
// reflecting part of the Principled BSDF, + velvet_brdf.
glm::dvec3 principled_brdf(const PrincipledParams& p, const glm::dvec3& wo, const glm::dvec3& wi);

}  // namespace shaders_ref
