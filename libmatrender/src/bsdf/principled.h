#pragma once
// The Principled BSDF of Blender 3.4 Cycles restricted to what matpredict's materials use: a
// diffuse lobe weighted (1 - metallic)(1 - transmission) base colour, a sheen lobe on top of it,
// a GGX specular lobe with the interpolated Fresnel, a clearcoat lobe, and glass (a GGX
// reflection and a GGX refraction) of weight transmission (1 - metallic) (svm_closure.h,
// CLOSURE_BSDF_PRINCIPLED_ID), all scaled by the Alpha input, whose complement a transparent
// lobe passes straight through. A material without a lobe pays nothing for it: specular 0 and
// metallic 0 make no specular lobe at all; sheen, clearcoat and transmission 0 and alpha 1 (the
// defaults) no sheen, clearcoat, glass or transparent lobes. Beside it, the Velvet BSDF that
// Blender's glTF importer adds for KHR_materials_sheen (velvet_lobe.h), made only where the
// velvet colour is not black.
#include <array>
#include <cstdint>

#include <glm/glm.hpp>

#include "bsdf/fresnel.h"
#include "bsdf/lobe_mixture.h"
#include "bsdf/microfacet_multiscatter.h"
#include "matrender/material.h"

namespace matrender {

// A material's parameters after texture lookups, for one shading point.
struct PrincipledInputs {
  // Blender's defaults.
  PrincipledInputs();
  // The material's constants, textures left out.
  explicit PrincipledInputs(const Material& material);

  std::array<glm::vec3, matmaterial::kMaterialParameterCount> values;  // by MaterialParameter; scalars in x
  DiffuseModel diffuse_model = DiffuseModel::Principled;
  SpecularDistribution distribution = SpecularDistribution::GGX;

  glm::vec3 color(MaterialParameter p) const { return values[static_cast<size_t>(p)]; }
  float scalar(MaterialParameter p) const { return values[static_cast<size_t>(p)].x; }
  PrincipledInputs& set(MaterialParameter p, const glm::vec3& value) {
    values[static_cast<size_t>(p)] = value;
    return *this;
  }
  PrincipledInputs& set(MaterialParameter p, float value) { return set(p, glm::vec3(value)); }
  // The Alpha input in [0, 1]: the fraction of the light the surface scatters and emits.
  float coverage() const { return glm::clamp(scalar(MaterialParameter::Alpha), 0.0f, 1.0f); }
};

// What the lobes take from the material inputs alone, before any view direction: computed once
// per material when no input is textured, once per shading point otherwise.
struct PrincipledParameters {
  // The estimator and walk: Cycles 3.4's own (cycles_parity) or those that converge to the
  // integral (the defaults).
  explicit PrincipledParameters(const PrincipledInputs& inputs,
                                ClearcoatEstimator estimator = ClearcoatEstimator::Integral,
                                MultiscatterWalk walk = MultiscatterWalk::Exact);

  glm::vec3 diffuse_weight{0.0f};  // (1 - metallic)(1 - transmission) base colour
  glm::vec3 sheen_weight{0.0f};    // sheen (1 - metallic)(1 - transmission) mix(1, base tint, sheen_tint)
  bool sheen_enabled;              // Cycles' cutoff: sheen and the diffuse weight both above 1e-5
  DiffuseModel diffuse_model;
  float roughness;
  float alpha;                     // GGX alpha = roughness^2
  bool singular;                   // a perfect mirror
  float specular_weight;           // 1 - transmission (1 - metallic)
  bool specular_enabled;           // specular > 0 or metallic > 0, and a specular weight
  // Multiscatter GGX asked for and roughness above Cycles' 0.075, below which it stays single.
  bool multiscatter = false;
  MultiscatterWalk multiscatter_walk;
  InterpolatedFresnel fresnel;
  float clearcoat_weight = 0.0f;   // 0.25 clearcoat
  float clearcoat_alpha = 0.0f;    // GTR1 alpha = clearcoat_roughness^2
  bool clearcoat_enabled;          // clearcoat above Cycles' cutoff 1e-5
  ClearcoatEstimator clearcoat_estimator;
  // Glass, of weight transmission (1 - metallic): a GGX reflection with the interpolated Fresnel
  // of cspec0 mix(1, base, specular_tint) and a GGX refraction tinted by the base colour.
  float glass_weight = 0.0f;
  bool glass_enabled;              // the glass weight above Cycles' cutoff 1e-5
  float ior = 1.45f;               // the material's, entering through the front face
  glm::vec3 glass_cspec0{1.0f};
  float glass_f0 = 0.0f;           // fresnel_dielectric_cos(1, ior), the same for ior and 1 / ior
  glm::vec3 refraction_tint{0.0f};
  float refraction_alpha = 0.0f;   // (1 - (1 - roughness)(1 - transmission_roughness))^2
  // Coverage: every weight above is scaled by it, and 1 - coverage passes straight through.
  float coverage = 1.0f;           // the Alpha input
  bool transparent;                // 1 - coverage above Cycles' cutoff 1e-5
  // The Velvet BSDF added to the Principled one: its colour as the weight, whatever the
  // Principled BSDF's alpha, metallic and transmission are (the Add Shader after it).
  glm::vec3 velvet_weight{0.0f};
  float velvet_sigma = 1.0f;
  bool velvet_enabled;             // the colour's average at or above Cycles' cutoff 1e-5
};

// What a hit adds to the shading frame, in its local coordinates.
struct ShadingGeometry {
  // Cycles' sd->N: the interpolated normal before normal mapping and ensure_valid_reflection.
  // Where it differs from +Z the diffuse lobe carries Cycles' bump shadowing term.
  glm::vec3 smooth_normal{0.0f, 0.0f, 1.0f};
  // The normal of the lobes whose Normal input is left unlinked (the clearcoat, the velvet): the
  // smooth normal made valid for reflection, as Cycles makes every closure's normal; it differs
  // from +Z only under a normal map.
  glm::vec3 unmapped_normal{0.0f, 0.0f, 1.0f};
  // The viewer is on the side the triangle's winding faces: glass is entered, not left.
  bool front_face = true;
};

// Adds the lobes seen from wo (local shading frame, +Z = shading normal) to the empty `lobes`
// and finishes it. walk_seed: the random numbers of a multiscatter lobe's walk.
void add_principled_lobes(const PrincipledParameters& parameters, const glm::vec3& wo, const ShadingGeometry& geometry,
                          LobeMixture* lobes, uint32_t walk_seed = 0);

}  // namespace matrender
