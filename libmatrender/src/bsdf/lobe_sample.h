#pragma once
#include <glm/glm.hpp>

#include "bsdf/bxdf_flags.h"

namespace matrender {

// A direction drawn by one lobe. A non-specular lobe gives only wi: the mixture evaluates every
// lobe there for the value and the pdf. A specular lobe also gives the weight its delta carries
// along wi (f cos / pdf of the delta: its reflectance), which no evaluation can give. A lobe whose
// value is itself an estimate (multiscatter GGX) gives its own f cos and pdf for wi, so that the
// sample's weight is its walk's throughput, not the ratio of two independent estimates.
struct LobeSample {
  glm::vec3 wi{0.0f};
  glm::vec3 specular_weight{0.0f};
  bool has_value = false;
  glm::vec3 value{0.0f};
  float pdf = 0.0f;
};

// Every lobe has the same methods (the mixture, lobe_mixture.h, holds any of them), all in the
// local shading frame (+Z = shading normal, directions pointing away, wo fixed at construction):
//   BxDFFlags flags() const;
//   float sample_weight() const;   how often the mixture picks it (Cycles' closure sample_weight)
//   glm::vec3 eval(const glm::vec3& wi, float* pdf) const;   f cos(theta_i), and the pdf of
//                                                            sample() making wi; 0 for a delta
//   bool sample(glm::vec2 u, LobeSample* out) const;         false when no direction is made

}  // namespace matrender
