#include "bsdf/principled.h"

#include <algorithm>

#include "bsdf/microfacet_ggx.h"
#include "matbase/image/srgb.h"
#include "util/channel_average.h"

namespace matrender {
namespace {

// Cycles' CLOSURE_WEIGHT_CUTOFF: closures weaker than this are not made.
constexpr float kClosureWeightCutoff = 1e-5f;

// Cycles' glass: the Fresnel reflectance toward the viewer splits the glass weight between a
// reflection (whose interpolated Fresnel is 1 unless specular tint colours it) and a refraction
// tinted by the base colour; the refraction keeps at least 1e-4 of it, even at total internal
// reflection, where it samples nothing. Closures below the cutoff are not made.
void add_glass_lobes(const PrincipledParameters& p, const glm::vec3& wo, bool front_face, LobeMixture* lobes) {
  const float eta = front_face ? p.ior : 1.0f / p.ior;
  const float reflectance = fresnel_dielectric_cos(wo.z, eta);
  const float reflection_weight = p.glass_weight * reflectance;
  if (reflection_weight >= kClosureWeightCutoff)
    lobes->add(
        GgxReflectionLobe(reflection_weight, InterpolatedFresnel(p.glass_cspec0, eta, p.glass_f0), p.alpha, p.singular, wo));
  const glm::vec3 refraction_weight = p.refraction_tint * (p.glass_weight * std::max(1e-4f, 1.0f - reflectance));
  if (channel_average(refraction_weight) >= kClosureWeightCutoff)
    lobes->add(GgxTransmissionLobe(refraction_weight, eta, p.refraction_alpha, wo));
}

}  // namespace

PrincipledInputs::PrincipledInputs() {
  // Every SurfacePoint starts with one: computed once, copied after.
  static const std::array<glm::vec3, matmaterial::kMaterialParameterCount> defaults = [] {
    std::array<glm::vec3, matmaterial::kMaterialParameterCount> table{};
    for (const matmaterial::MaterialParameterInfo& info : matmaterial::kMaterialParameters)
      table[static_cast<size_t>(info.id)] = glm::vec3(static_cast<float>(info.default_value));
    return table;
  }();
  values = defaults;
}

PrincipledInputs::PrincipledInputs(const Material& material)
    : diffuse_model(material.diffuse_model), distribution(material.distribution) {
  for (size_t i = 0; i < values.size(); ++i) values[i] = material.parameters[i].value;
}

PrincipledParameters::PrincipledParameters(const PrincipledInputs& inputs, ClearcoatEstimator estimator,
                                           MultiscatterWalk walk)
    : diffuse_model(inputs.diffuse_model), multiscatter_walk(walk), clearcoat_estimator(estimator) {
  const glm::vec3 base = glm::max(inputs.color(MaterialParameter::BaseColor), glm::vec3(0.0f));
  const float metallic = glm::clamp(inputs.scalar(MaterialParameter::Metallic), 0.0f, 1.0f);
  const float specular = glm::clamp(inputs.scalar(MaterialParameter::Specular), 0.0f, 1.0f);
  const float tint_amount = glm::clamp(inputs.scalar(MaterialParameter::SpecularTint), 0.0f, 1.0f);
  roughness = glm::clamp(inputs.scalar(MaterialParameter::Roughness), 0.0f, 1.0f);
  alpha = roughness * roughness;
  singular = alpha * alpha <= kGgxSingularAlpha2;

  const float transmission = glm::clamp(inputs.scalar(MaterialParameter::Transmission), 0.0f, 1.0f);
  const float dielectric_opaque = (1.0f - metallic) * (1.0f - transmission);
  diffuse_weight = dielectric_opaque * base;
  glass_weight = transmission * (1.0f - metallic);
  specular_weight = 1.0f - glass_weight;
  specular_enabled = (specular > 0.0f || metallic > 0.0f) && specular_weight > kClosureWeightCutoff;
  // svm_closure.h: "roughness <= 0.075f" keeps single-scatter GGX.
  multiscatter = inputs.distribution == SpecularDistribution::MultiscatterGGX && roughness > 0.075f;

  // The base colour's hue: tint = base / lum (white for black), for the specular and sheen tints.
  const float lum = matbase::rec709_luminance(base);  // Cycles' linear_rgb_to_gray for scene-linear
  const glm::vec3 tint = lum > 0.0f ? base / lum : glm::vec3(1.0f);

  const float sheen = glm::clamp(inputs.scalar(MaterialParameter::Sheen), 0.0f, 1.0f);
  sheen_enabled = sheen > kClosureWeightCutoff && dielectric_opaque > kClosureWeightCutoff;
  if (sheen_enabled) {
    const float sheen_tint = glm::clamp(inputs.scalar(MaterialParameter::SheenTint), 0.0f, 1.0f);
    sheen_weight = sheen * dielectric_opaque * glm::mix(glm::vec3(1.0f), tint, sheen_tint);
  }

  // cspec0 = mix(0.08 specular mix(1, tint, specular_tint), base, metallic).
  const glm::vec3 dielectric = 0.08f * specular * glm::mix(glm::vec3(1.0f), tint, tint_amount);
  // principled_specular_ior makes ((ior - 1) / (ior + 1))^2 = 0.08 specular: F(1) needs no evaluation.
  fresnel = InterpolatedFresnel(glm::mix(dielectric, base, metallic), principled_specular_ior(specular),
                                0.08f * specular);

  glass_enabled = glass_weight > kClosureWeightCutoff;
  if (glass_enabled) {
    ior = std::max(inputs.scalar(MaterialParameter::Ior), 1e-5f);  // Cycles' lower bound
    glass_f0 = fresnel_dielectric_cos(1.0f, ior);
    glass_cspec0 = glm::mix(glm::vec3(1.0f), base, tint_amount);
    refraction_tint = base;
    const float transmission_roughness =
        glm::clamp(inputs.scalar(MaterialParameter::TransmissionRoughness), 0.0f, 1.0f);
    const float refraction_roughness = 1.0f - (1.0f - roughness) * (1.0f - transmission_roughness);
    refraction_alpha = refraction_roughness * refraction_roughness;
  }

  const float clearcoat = glm::clamp(inputs.scalar(MaterialParameter::Clearcoat), 0.0f, 1.0f);
  clearcoat_enabled = clearcoat > kClosureWeightCutoff;
  if (clearcoat_enabled) {
    const float clearcoat_roughness = glm::clamp(inputs.scalar(MaterialParameter::ClearcoatRoughness), 0.0f, 1.0f);
    clearcoat_weight = 0.25f * clearcoat;
    clearcoat_alpha = clearcoat_roughness * clearcoat_roughness;
  }

  // Cycles mixes the whole BSDF (emission included) with a transparent BSDF by Alpha
  // (PrincipledBsdfNode::expand in scene/shader_nodes.cpp): every closure weight times alpha.
  coverage = inputs.coverage();
  transparent = 1.0f - coverage > kClosureWeightCutoff;
  if (transparent) {
    diffuse_weight *= coverage;
    sheen_weight *= coverage;
    specular_weight *= coverage;
    clearcoat_weight *= coverage;
    glass_weight *= coverage;
    // Nothing is left of a surface with no coverage but its transparency.
    if (!(coverage > kClosureWeightCutoff)) sheen_enabled = specular_enabled = clearcoat_enabled = glass_enabled = false;
  }

  // svm_closure.h, CLOSURE_BSDF_ASHIKHMIN_VELVET_ID: "sigma = saturatef(param1)"; bsdf_alloc
  // drops a closure whose sample weight, the weight's average, is below the cutoff.
  velvet_weight = glm::max(inputs.color(MaterialParameter::VelvetColor), glm::vec3(0.0f));
  velvet_enabled = channel_average(velvet_weight) >= kClosureWeightCutoff;
  velvet_sigma = glm::clamp(inputs.scalar(MaterialParameter::VelvetSigma), 0.0f, 1.0f);
}

void add_principled_lobes(const PrincipledParameters& p, const glm::vec3& wo, const ShadingGeometry& geometry,
                          LobeMixture* lobes, uint32_t walk_seed) {
  const DiffuseLobe diffuse(p.diffuse_weight, p.diffuse_model, p.roughness, wo, geometry.smooth_normal);
  if (diffuse.sample_weight() > 0.0f) lobes->add(diffuse);
  // Added even where its sample weight is 0 (seen head-on): like Cycles' closure it then still
  // counts in every evaluation, only BSDF sampling never picks it.
  if (p.sheen_enabled) lobes->add(SheenLobe(p.sheen_weight, wo));
  if (p.specular_enabled && p.multiscatter)
    lobes->add(MultiscatterGgxLobe(p.specular_weight, p.fresnel, p.alpha, wo, walk_seed, p.multiscatter_walk));
  else if (p.specular_enabled)
    lobes->add(GgxReflectionLobe(p.specular_weight, p.fresnel, p.alpha, p.singular, wo));
  if (p.glass_enabled) add_glass_lobes(p, wo, geometry.front_face, lobes);
  if (p.clearcoat_enabled)
    lobes->add(
        ClearcoatLobe(p.clearcoat_weight, p.clearcoat_alpha, p.clearcoat_estimator, wo, geometry.unmapped_normal));
  if (p.transparent) lobes->add(TransparentLobe(glm::vec3(1.0f - p.coverage), wo));
  if (p.velvet_enabled) lobes->add(VelvetLobe(p.velvet_weight, p.velvet_sigma, wo, geometry.unmapped_normal));
  lobes->finish();
}

}  // namespace matrender
