#pragma once
// The specular lobe with Cycles 3.4's "Multiscatter GGX" distribution (Principled BSDF, for
// roughness above 0.075): reflection off a GGX microsurface including the light that bounces
// between microfacets before it leaves, by the random walk of microfacet_multiscatter.h.
// Its value is itself a Monte Carlo estimate (the single bounce in closed form plus the walk's
// later bounces toward wi) and its pdf the approximation multiscatter_pdf, as in Cycles: a sample
// carries the walk's throughput, so sample() gives its own value rather than one evaluated anew.
// The Fresnel colour is Cycles' interpolated Fresnel (fresnel.h) at every microfacet the walk
// reflects from. With MultiscatterWalk::Cycles34 the evaluation keeps Cycles' shortcuts: its
// heights (microfacet_multiscatter.h), the first bounce's colour taken at the half vector of wo
// and wi, and the later bounces' terms carrying the colour twice.
#include <algorithm>
#include <cstdint>

#include <glm/glm.hpp>

#include "bsdf/bxdf_flags.h"
#include "bsdf/fresnel.h"
#include "bsdf/lobe_sample.h"
#include "bsdf/microfacet_multiscatter.h"
#include "util/channel_average.h"

namespace matrender {

class MultiscatterGgxLobe {
 public:
  // Cycles clamps the walk's alpha to [1e-4, 1]; seed: the walk's random numbers.
  MultiscatterGgxLobe(float weight, const InterpolatedFresnel& fresnel, float alpha, const glm::vec3& wo, uint32_t seed,
                      MultiscatterWalk walk = MultiscatterWalk::Exact)
      : weight_(weight), fresnel_(fresnel), alpha_(std::clamp(alpha, 1e-4f, 1.0f)), wo_(wo), walk_(walk), random_(seed) {}

  BxDFFlags flags() const { return BxDFFlags::GlossyReflection; }
  // As single-scatter GGX: the closure weight times the Fresnel reflectance toward the viewer.
  float sample_weight() const { return weight_ * channel_average(fresnel_(std::max(wo_.z, 0.0f))); }

  glm::vec3 eval(const glm::vec3& wi, float* pdf) const {
    *pdf = 0.0f;
    if (wo_.z <= 0.0f || wi.z <= 0.0f) return glm::vec3(0.0f);
    *pdf = multiscatter_pdf(wo_, wi, alpha_);
    return weight_ * walk_toward(wi);
  }

  bool sample(glm::vec2 /*u*/, LobeSample* out) const {
    if (wo_.z <= 0.0f) return false;
    glm::vec3 throughput;
    if (!walk_out(&out->wi, &throughput) || !(out->wi.z > 0.0f)) return false;
    out->pdf = multiscatter_pdf(wo_, out->wi, alpha_);
    out->value = weight_ * throughput * out->pdf;
    out->has_value = true;
    return out->pdf > 0.0f;
  }

 private:
  // f cos toward wi, estimated: the walk starts from the shallower of the two directions
  // (less noise; the BSDF is reciprocal), the single bounce in closed form with the
  // height-correlated G2 = 1 / (1 + Lambda(in) + Lambda(out)), every later microfacet adding what
  // it reflects toward the other direction times the masking from its height.
  glm::vec3 walk_toward(glm::vec3 wi) const {
    const bool cycles = walk_ == MultiscatterWalk::Cycles34;
    glm::vec3 start = wo_;
    bool swapped = false;
    if (wi.z < start.z) {
      std::swap(start, wi);
      swapped = true;
    }
    if (start.z < 1e-5f || wi.z < 1e-5f) return glm::vec3(0.0f);
    WalkState state;
    state.lambda = multiscatter_lambda(-start, alpha_);
    const float escape_lambda = multiscatter_lambda(wi, alpha_);
    const glm::vec3 half = glm::normalize(start + wi);
    const float g2 = 1.0f / (1.0f - (state.lambda + 1.0f) + escape_lambda);
    const glm::vec3 single_colour = fresnel_(glm::dot(start, half));
    glm::vec3 value = single_colour * (g2 * 0.25f / start.z * multiscatter_ggx_d(half, alpha_));
    glm::vec3 throughput = cycles ? single_colour : glm::vec3(1.0f);
    glm::vec3 ray = -start;
    for (int order = 0; order < kMaxOrder; ++order) {
      if (!sample_next_height(ray, random_.next(), walk_, &state)) break;
      const float uy = random_.next(), ux = random_.next();
      const glm::vec3 m = sample_visible_normal_any_side(-ray, alpha_, ux, uy);
      if (order > 0) {
        const float phase = reflection_phase(ray, state.lambda, wi, alpha_);
        const glm::vec3 colour = cycles ? throughput : fresnel_(glm::dot(-ray, glm::normalize(wi - ray)));
        value += throughput * colour * (phase * masking_at_height(wi, state.c, escape_lambda));
      }
      if (order + 1 < kMaxOrder) {
        if (!cycles || order > 0) throughput *= fresnel_(glm::dot(-ray, m));
        ray = ray - 2.0f * glm::dot(ray, m) * m;
        state.lambda = multiscatter_lambda(ray, alpha_);
        state.g1 = masking_at_height(ray, state.c, state.lambda);
      }
    }
    if (swapped) value *= std::abs(start.z / wi.z);
    return value;
  }

  // A walk from the viewer until the ray leaves the microsurface: its direction and throughput
  // (the product of the microfacets' Fresnel colours). False when it is still inside after
  // kMaxOrder bounces.
  bool walk_out(glm::vec3* wi, glm::vec3* throughput) const {
    WalkState state;
    glm::vec3 ray = -wo_;
    state.lambda = multiscatter_lambda(ray, alpha_);
    glm::vec3 carried(1.0f);
    for (int order = 0; order < kMaxOrder; ++order) {
      if (!sample_next_height(ray, random_.next(), walk_, &state)) {
        *wi = ray;
        *throughput = carried;
        return true;
      }
      const float uy = random_.next(), ux = random_.next();
      const glm::vec3 m = sample_visible_normal_any_side(-ray, alpha_, ux, uy);
      carried *= fresnel_(glm::dot(-ray, m));
      ray = ray - 2.0f * glm::dot(ray, m) * m;
      state.lambda = multiscatter_lambda(ray, alpha_);
      state.g1 = masking_at_height(ray, state.c, state.lambda);
    }
    return false;
  }

  static constexpr int kMaxOrder = 10;  // Cycles' walk length
  float weight_;
  InterpolatedFresnel fresnel_;
  float alpha_;
  glm::vec3 wo_;
  MultiscatterWalk walk_;
  mutable WalkRandom random_;  // advanced by every estimate
};

}  // namespace matrender
