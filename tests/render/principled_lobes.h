#pragma once
// The Principled BSDF's diffuse and specular lobes evaluated apart, for tests against the reference shaders.
#include <glm/glm.hpp>

#include "bsdf/principled.h"

// f cos of the diffuse lobes alone: the diffuse one and the sheen (which Cycles labels diffuse).
inline glm::vec3 diffuse_value(const matrender::LobeMixture& bsdf, const glm::vec3& wi) {
  float pdf;
  return bsdf.eval(wi, matrender::BxDFFlags::Diffuse, &pdf);
}

// f cos of the glossy lobes, the reflecting ones (GGX specular, clearcoat, glass reflection) for
// wi above the surface and the glass refraction below it (0 for a perfect mirror, which has no
// density).
inline glm::vec3 specular_value(const matrender::LobeMixture& bsdf, const glm::vec3& wi) {
  float pdf;
  return bsdf.eval(wi, matrender::BxDFFlags::Glossy | matrender::BxDFFlags::Specular, &pdf);
}

// The Principled BSDF's lobes seen from wo, in the local shading frame.
// front_face: the viewer is outside the glass.
inline matrender::LobeMixture principled_bsdf(
    const matrender::PrincipledInputs& inputs, const glm::vec3& wo,
    matrender::ClearcoatEstimator estimator = matrender::ClearcoatEstimator::Integral, bool front_face = true) {
  matrender::LobeMixture lobes;
  matrender::ShadingGeometry geometry;
  geometry.front_face = front_face;
  matrender::add_principled_lobes(matrender::PrincipledParameters(inputs, estimator), wo, geometry, &lobes);
  return lobes;
}
