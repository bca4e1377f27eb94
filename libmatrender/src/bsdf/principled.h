#pragma once
// The Principled BSDF of Blender 3.4 Cycles restricted to what matpredict's materials use: a
// diffuse lobe weighted (1 - metallic) * base colour, a sheen lobe on top of it, a GGX specular
// lobe with the interpolated Fresnel and a clearcoat lobe (svm_closure.h,
// CLOSURE_BSDF_PRINCIPLED_ID). A material without a lobe pays nothing for it: specular 0 and
// metallic 0 make no specular lobe at all, sheen 0 and clearcoat 0 (the defaults) no sheen and
// no clearcoat lobe.
#include <array>

#include <glm/glm.hpp>

#include "bsdf/fresnel.h"
#include "bsdf/lobe_mixture.h"
#include "matrender/material.h"

namespace matrender {

// A material's parameters after texture lookups, for one shading point.
struct PrincipledInputs {
  // Blender's defaults.
  PrincipledInputs();
  // The material's constants, textures left out.
  explicit PrincipledInputs(const Material& material);

  std::array<glm::vec3, matgeom::kMaterialParameterCount> values;  // by MaterialParameter; scalars in x
  DiffuseModel diffuse_model = DiffuseModel::Principled;

  glm::vec3 color(MaterialParameter p) const { return values[static_cast<size_t>(p)]; }
  float scalar(MaterialParameter p) const { return values[static_cast<size_t>(p)].x; }
  PrincipledInputs& set(MaterialParameter p, const glm::vec3& value) {
    values[static_cast<size_t>(p)] = value;
    return *this;
  }
  PrincipledInputs& set(MaterialParameter p, float value) { return set(p, glm::vec3(value)); }
};

// What the lobes take from the material inputs alone, before any view direction: computed once
// per material when no input is textured, once per shading point otherwise.
struct PrincipledParameters {
  explicit PrincipledParameters(const PrincipledInputs& inputs,
                                ClearcoatEstimator estimator = ClearcoatEstimator::Integral);

  glm::vec3 diffuse_weight{0.0f};  // (1 - metallic) base colour
  glm::vec3 sheen_weight{0.0f};    // sheen (1 - metallic) mix(1, base tint, sheen_tint)
  bool sheen_enabled;              // Cycles' cutoff: sheen and 1 - metallic both above 1e-5
  DiffuseModel diffuse_model;
  float roughness;
  float alpha;                     // GGX alpha = roughness^2
  bool singular;                   // a perfect mirror
  bool specular_enabled;           // specular > 0 or metallic > 0
  InterpolatedFresnel fresnel;
  float clearcoat_weight = 0.0f;   // 0.25 clearcoat
  float clearcoat_alpha = 0.0f;    // GTR1 alpha = clearcoat_roughness^2
  bool clearcoat_enabled;          // clearcoat above Cycles' cutoff 1e-5
  ClearcoatEstimator clearcoat_estimator;
};

// The normals the lobes use besides the shading normal (+Z), in the local shading frame; +Z
// where they coincide with it.
struct LobeNormals {
  // Cycles' sd->N: the interpolated normal before normal mapping and ensure_valid_reflection.
  // Where it differs from +Z the diffuse lobe carries Cycles' bump shadowing term.
  glm::vec3 smooth{0.0f, 0.0f, 1.0f};
  // The clearcoat's: the smooth normal made valid for reflection, as Cycles makes the unlinked
  // Clearcoat Normal input; it differs from +Z only under a normal map.
  glm::vec3 clearcoat{0.0f, 0.0f, 1.0f};
};

// Adds the lobes seen from wo (local shading frame, +Z = shading normal) to the empty `lobes`
// and finishes it.
void add_principled_lobes(const PrincipledParameters& parameters, const glm::vec3& wo, const LobeNormals& normals,
                          LobeMixture* lobes);

}  // namespace matrender
