#pragma once
// Multiple scattering on an isotropic GGX microsurface as a random walk (Heitz, Hanika, d'Eon and
// Dachsbacher 2016, "Multiple-Scattering Microfacet BSDFs with the Smith Model"), the pieces of
// Cycles 3.4's "Multiscatter GGX" (kernel/closure/bsdf_microfacet_multi.h and _impl.h, taken from
// the paper's supplemental code). The microsurface has uniformly distributed heights in [-1, 1]; a
// ray goes down into it, meets microfacets at heights drawn from the visible-height distribution,
// reflects off normals drawn from the visible normals, and leaves when no microfacet stops it.
// Local frame: +Z is the shading normal.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/glm.hpp>

#include "sampling/warp.h"

namespace matrender {

// Smith's Lambda of GGX for a direction of either hemisphere: Lambda(w) = (sqrt(1 + alpha^2
// tan^2) - 1) / 2 above, and -1 - Lambda(-w) below, as the walk needs it (the paper's eq. 10).
inline float multiscatter_lambda(const glm::vec3& w, float alpha) {
  if (w.z > 0.9999f) return 0.0f;
  if (w.z < -0.9999f) return -0.9999f;
  const float inv_z2 = 1.0f / std::max(w.z * w.z, 1e-7f);
  float v = std::sqrt(1.0f + alpha * alpha * (w.x * w.x + w.y * w.y) * inv_z2);
  if (w.z <= 0.0f) v = -v;
  return 0.5f * (v - 1.0f);
}

// The uniform height distribution's CDF on [-1, 1] and its inverse.
inline float height_cdf(float h) { return std::clamp(0.5f * (h + 1.0f), 0.0f, 1.0f); }
inline float height_of_cdf(float c) { return 2.0f * std::clamp(c, 0.0f, 1.0f) - 1.0f; }

// Masking of a ray leaving along w from the height of CDF c: c^Lambda (the paper's eq. 13).
inline float masking_at_height(const glm::vec3& w, float c, float lambda) {
  if (w.z > 0.9999f) return 1.0f;
  if (w.z < 1e-5f) return 0.0f;
  return std::pow(c, lambda);
}

// The walk's state between microfacets: its height's CDF, the masking from there and Lambda of
// its direction.
struct WalkState {
  float c = 1.0f;  // height_cdf of the current height (1: above the surface)
  float g1 = 0.0f;
  float lambda = 0.0f;
  float height() const { return height_of_cdf(c); }
};

// How the walk is taken: as the paper derives it, or with Cycles 3.4's shortcuts (below and in
// multiscatter_ggx_lobe.h), which make its evaluation lose energy when it walks from a shallow
// direction (a white rough metal seen from above reflects 0.88 instead of 1 at alpha 1).
enum class MultiscatterWalk { Exact, Cycles34 };

// The next height the ray along w meets a microfacet at, drawn with u (the paper's algorithm 2:
// C1(h') = C1(h) / (1 - u)^(1 / Lambda)); false when the ray leaves the microsurface instead.
// Cycles 3.4 puts a rising ray (Lambda >= 0) that meets the surface again at the top (C1 = 1).
inline bool sample_next_height(const glm::vec3& w, float u, MultiscatterWalk walk, WalkState* s) {
  if (w.z > 0.9999f) return false;
  if (w.z < -0.9999f) {
    s->c *= u;
  } else if (std::abs(w.z) >= 1e-4f) {
    if (u > 1.0f - s->g1) return false;
    if (walk == MultiscatterWalk::Cycles34 && s->lambda >= 0.0f)
      s->c = 1.0f;
    else
      s->c = std::min(1.0f, s->c * std::pow(1.0f - u, -1.0f / s->lambda));
  } else {
    return true;  // a ray in the mean plane keeps its height
  }
  s->g1 = masking_at_height(w, s->c, s->lambda);
  return true;
}

// A slope drawn from the visible slopes of the standard (alpha 1) GGX surface seen at cosine
// cos_i, which may be negative (Heitz and d'Eon 2014, "Importance Sampling Microfacet-Based BSDFs
// using the Distribution of Visible Normals", supplemental: the x slope by inverting its CDF, the
// y slope by a rational fit of its inverse CDF).
inline glm::vec2 sample_visible_slope_standard(float cos_i, float ux, float uy) {
  if (cos_i > 0.9999f || std::abs(cos_i) < 1e-6f) {
    const float r = std::sqrt(ux / std::max(1.0f - ux, 1e-7f));
    const float phi = 2.0f * kPi * uy;
    return {r * std::cos(phi), r * std::sin(phi)};
  }
  const float sin_i = std::sqrt(std::max(0.0f, 1.0f - cos_i * cos_i));
  const float tan_i = sin_i / cos_i;
  const float projected_area = 0.5f * (cos_i + 1.0f);
  if (projected_area < 1e-4f) return glm::vec2(0.0f);
  const float a = 2.0f * ux * projected_area / cos_i - 1.0f;
  float tmp = a * a - 1.0f;
  if (std::abs(tmp) < 1e-7f) return glm::vec2(0.0f);
  tmp = 1.0f / tmp;
  const float d = std::sqrt(std::max(0.0f, tan_i * tan_i * tmp * tmp - (a * a - tan_i * tan_i) * tmp));
  const float slope_x_high = tan_i * tmp + d;
  const float slope_x = (a < 0.0f || slope_x_high > 1.0f / tan_i) ? tan_i * tmp - d : slope_x_high;
  const float u2 = uy >= 0.5f ? 2.0f * (uy - 0.5f) : 2.0f * (0.5f - uy);
  const float z = (u2 * (u2 * (u2 * 0.27385f - 0.73369f) + 0.46341f)) /
                  (u2 * (u2 * (u2 * 0.093073f + 0.309420f) - 1.0f) + 0.597999f);
  const float slope_y = z * std::sqrt(1.0f + slope_x * slope_x);
  return {slope_x, uy >= 0.5f ? slope_y : -slope_y};
}

// A microfacet normal drawn from those visible along wi (either hemisphere), by stretching to
// alpha 1, sampling the slope, rotating and unstretching (Heitz and d'Eon 2014, section 4).
inline glm::vec3 sample_visible_normal_any_side(const glm::vec3& wi, float alpha, float ux, float uy) {
  const glm::vec3 stretched = glm::normalize(glm::vec3(alpha * wi.x, alpha * wi.y, wi.z));
  const glm::vec2 slope = sample_visible_slope_standard(stretched.z, ux, uy);
  const float len = std::sqrt(stretched.x * stretched.x + stretched.y * stretched.y);
  const float cos_phi = len > 0.0f ? stretched.x / len : 1.0f, sin_phi = len > 0.0f ? stretched.y / len : 0.0f;
  const float sx = alpha * (cos_phi * slope.x - sin_phi * slope.y);
  const float sy = alpha * (sin_phi * slope.x + cos_phi * slope.y);
  return glm::normalize(glm::vec3(-sx, -sy, 1.0f));
}

// D(m) of GGX as Cycles' walk evaluates it (bounded below by 1e-7 in the denominator).
inline float multiscatter_ggx_d(const glm::vec3& m, float alpha) {
  const float z2 = m.z * m.z, a2 = alpha * alpha;
  const float t = (1.0f - z2) + a2 * z2;
  return a2 / std::max(kPi * t * t, 1e-7f);
}

// The reflection phase function of a ray along w (going into the surface, Lambda `lambda` for
// it) meeting a microfacet and leaving toward wo (the paper's eq. 17 for a mirror microfacet).
inline float reflection_phase(const glm::vec3& w, float lambda, const glm::vec3& wo, float alpha) {
  if (w.z > 0.9999f) return 0.0f;
  const glm::vec3 wh = glm::normalize(wo - w);
  if (wh.z < 0.0f) return 0.0f;
  const float projected_area = w.z < -0.9999f ? 1.0f : lambda * w.z;
  const float cos_wh = glm::dot(-w, wh);
  if (cos_wh < 0.0f) return 0.0f;
  return cos_wh * 0.25f / std::max(projected_area * cos_wh, 1e-7f) * multiscatter_ggx_d(wh, alpha);
}

// Cycles' fit of the directional albedo of single-scatter GGX at alpha r, for its pdf below.
inline float single_scatter_albedo_fit(float r) {
  float albedo = 0.806495f * std::exp(-1.98712f * r * r) + 0.199531f;
  albedo -= ((((((1.76741f * r - 8.43891f) * r + 15.784f) * r - 14.398f) * r + 6.45221f) * r - 1.19722f) * r +
             0.027803f) * r + 0.00568739f;
  return std::clamp(albedo, 0.0f, 1.0f);
}

// The walk's sampling density has no closed form. Cycles reports a mixture instead: the
// single-scatter visible-normal pdf weighed by the fitted albedo, and a cosine lobe for the rest.
// Used consistently by both strategies, MIS stays unbiased.
inline float multiscatter_pdf(const glm::vec3& wo, const glm::vec3& wi, float alpha) {
  const float d = multiscatter_ggx_d(glm::normalize(wo + wi), alpha);
  const float lambda = multiscatter_lambda(wo, alpha);
  const float single = 0.25f * d / std::max((1.0f + lambda) * wo.z, 1e-7f);
  const float albedo = single_scatter_albedo_fit(alpha);
  return albedo * single + (1.0f - albedo) * std::max(wi.z, 0.0f) * kInvPi;
}

// The walk's random numbers: a PCG-RXS-M-XS 32-bit generator (O'Neill 2014) per shading point,
// seeded from the path's sampler so an image depends on its seed only.
class WalkRandom {
 public:
  explicit WalkRandom(uint32_t seed) : state_(seed * 747796405u + 2891336453u) {}
  float next() {
    state_ = state_ * 747796405u + 2891336453u;
    uint32_t word = ((state_ >> ((state_ >> 28u) + 4u)) ^ state_) * 277803737u;
    word = (word >> 22u) ^ word;
    return static_cast<float>(word >> 8) * 0x1p-24f;
  }

 private:
  uint32_t state_;
};

}  // namespace matrender
