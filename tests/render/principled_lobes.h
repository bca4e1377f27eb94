#pragma once
// The Principled BSDF's two lobes evaluated apart, for tests against the reference shaders.
#include <glm/glm.hpp>

#include "bsdf/lobe_mixture.h"

// f cos of the diffuse lobe alone.
inline glm::vec3 diffuse_value(const matrender::LobeMixture& bsdf, const glm::vec3& wi) {
  float pdf;
  return bsdf.eval(wi, matrender::BxDFFlags::Diffuse, &pdf);
}

// f cos of the GGX specular lobe alone (0 for a perfect mirror, which has no density).
inline glm::vec3 specular_value(const matrender::LobeMixture& bsdf, const glm::vec3& wi) {
  float pdf;
  return bsdf.eval(wi, matrender::BxDFFlags::Glossy | matrender::BxDFFlags::Specular, &pdf);
}
