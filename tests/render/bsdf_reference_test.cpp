// The fast float Principled BSDF (libmatrender/src/bsdf) against the independent double-precision
// reference of shaders_ref, and the reference's quadrature against closed forms.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>

#include "matbase/pi.h"
#include "reference_params.h"
#include "principled_lobes.h"
#include "uniform_floats.h"
#include "velvet_condition.h"
#include "bsdf/principled.h"
#include "shaders_ref/directional_albedo.h"
#include "shaders_ref/principled_reference.h"

using matrender::BsdfSample;
using matrender::DiffuseModel;
using matrender::LobeMixture;
using matrender::MaterialParameter;
using matrender::PrincipledInputs;

namespace {

using matbase::kPi;

glm::dvec3 direction_with_cosine(double cos_theta) {
  return {std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta)), 0.0, cos_theta};
}

// A direction in the specular peak of wo: the mirror image of wo about a normal whose slope is
// within three GGX widths, tan(theta_m) < 3 alpha; a random direction if that falls below the
// horizon.
glm::vec3 direction_near_peak(const glm::vec3& wo, float alpha, UniformFloats& rng) {
  const float tan_m = 3.0f * alpha * rng.next();
  const float phi = 2.0f * static_cast<float>(kPi) * rng.next();
  const glm::vec3 m = glm::normalize(glm::vec3(tan_m * std::cos(phi), tan_m * std::sin(phi), 1.0f));
  const glm::vec3 wi = glm::normalize(2.0f * glm::dot(wo, m) * m - wo);
  return wi.z > 0.0f ? wi : random_upper_direction(rng);
}

// Material inputs over their whole range, with the edge values 0 and 1 of metallic and
// specular often enough to matter (metallic 1, dielectric, no specular lobe).
PrincipledInputs random_material(UniformFloats& rng, float min_roughness, float max_roughness) {
  const auto with_edges = [&rng](float p_zero, float p_one) {
    const float pick = rng.next();
    const float value = rng.next();
    return pick < p_zero ? 0.0f : pick < p_zero + p_one ? 1.0f : value;
  };
  PrincipledInputs in;
  in.set(MaterialParameter::BaseColor, glm::vec3{rng.next(), rng.next(), rng.next()});
  if (rng.next() < 0.05f) in.set(MaterialParameter::BaseColor, glm::vec3(0.0f));
  in.set(MaterialParameter::Metallic, with_edges(0.25f, 0.25f));
  in.set(MaterialParameter::Roughness, min_roughness + (max_roughness - min_roughness) * rng.next());
  in.set(MaterialParameter::Specular, with_edges(0.1f, 0.1f));
  in.set(MaterialParameter::SpecularTint, with_edges(0.3f, 0.2f));
  in.diffuse_model = rng.next() < 0.5f ? DiffuseModel::Principled : DiffuseModel::Lambert;
  in.set(MaterialParameter::Sheen, with_edges(0.5f, 0.1f));
  in.set(MaterialParameter::SheenTint, with_edges(0.2f, 0.2f));
  in.set(MaterialParameter::Clearcoat, with_edges(0.5f, 0.1f));
  in.set(MaterialParameter::ClearcoatRoughness, min_roughness + (max_roughness - min_roughness) * rng.next());
  in.set(MaterialParameter::Transmission, with_edges(0.6f, 0.1f));
  in.set(MaterialParameter::Ior, 1.0f + 1.5f * rng.next());
  // glTF's sheen as a velvet beside half of the materials, its width from Cycles' floor to 1.
  if (rng.next() < 0.5f) {
    in.set(MaterialParameter::VelvetColor, glm::vec3{rng.next(), rng.next(), rng.next()});
    in.set(MaterialParameter::VelvetSigma, with_edges(0.1f, 0.2f));
  }
  return in;
}

double average(const glm::dvec3& c) { return (c.x + c.y + c.z) / 3.0; }

// Float directions are unit vectors only to a few ulps, so a float evaluation sees directions off
// by ~2^-22 rad: the relative change this makes to the GGX lobe is its condition number times
// that. ln D(theta_m) changes at 4 tan / (alpha^2 + tan^2) per radian of the half vector (from
// Walter et al. 2007, eq. 33; up to 2 / alpha at the edge of the peak), and the half vector
// h = normalize(wo + wi) turns 1 / |wo + wi| = 1 / (2 cos_h) times as much as wi; ln G1(w)
// changes at Lambda'(theta) / (1 + Lambda) per radian (Heitz 2014, eq. 72; ~1 / cos(theta) at
// grazing).
double ggx_direction_condition(const glm::dvec3& wo, const glm::dvec3& wi, double alpha) {
  const glm::dvec3 h = glm::normalize(wo + wi);
  const double cos_h = glm::dot(wo, h);
  const double tan_m = std::sqrt(shaders_ref::tan2_theta(h));
  const double ndf_slope = 4.0 * tan_m / (alpha * alpha + tan_m * tan_m);
  const auto g1_slope = [alpha](const glm::dvec3& w) {
    const double tan2 = shaders_ref::tan2_theta(w);
    const double root = std::sqrt(1.0 + alpha * alpha * tan2);
    const double lambda_slope = alpha * alpha * std::sqrt(tan2) * (1.0 + tan2) / (2.0 * root);
    return lambda_slope / (1.0 + shaders_ref::ggx_lambda(w, alpha));
  };
  constexpr double kDirectionError = 0x1p-22;
  return kDirectionError * (ndf_slope / (2.0 * cos_h) + g1_slope(wo) + g1_slope(wi));
}

}  // namespace

TEST_CASE("Reference quadrature reproduces closed forms", "[render]") {
  const std::array<double, 5> roughness_values = {0.02, 0.1, 0.3, 0.6, 1.0};
  const std::array<double, 5> cos_values = {1.0, 0.7, 0.3, 0.05, 0.02};

  SECTION("Lambert albedo is 1 for base colour 1") {
    shaders_ref::PrincipledParams lambert;
    lambert.base_color = glm::dvec3(1.0);
    lambert.specular = 0.0;
    lambert.lambert_diffuse = true;
    for (double cos_o : cos_values) {
      const shaders_ref::LobeAlbedos a =
          shaders_ref::lobe_albedos(lambert, direction_with_cosine(cos_o));
      CHECK(a.diffuse.x == Approx(1.0).epsilon(1e-9));
      CHECK(a.specular.x == 0.0);
    }
  }
  SECTION("Sheen albedo seen head-on has a closed form") {
    // wo = n: wi.h = cos(theta/2). With u = 1 - cos(theta/2) the integral of (1 - wi.h)^5 cos(theta)
    // over the hemisphere is 2 pi int_0^U 4 (u^5 - 5 u^6 + 6 u^7 - 2 u^8) du, U = 1 - 1/sqrt(2).
    const double u = 1.0 - 1.0 / std::sqrt(2.0);
    const double closed_form = 2.0 * kPi * 4.0 *
                               (std::pow(u, 6) / 6.0 - 5.0 * std::pow(u, 7) / 7.0 + 6.0 * std::pow(u, 8) / 8.0 -
                                2.0 * std::pow(u, 9) / 9.0);
    shaders_ref::PrincipledParams cloth;
    cloth.base_color = glm::dvec3(0.0);  // no diffuse; a black base tints nothing: colour 1
    cloth.specular = 0.0;
    cloth.sheen = 1.0;
    const shaders_ref::LobeAlbedos a = shaders_ref::lobe_albedos(cloth, glm::dvec3(0.0, 0.0, 1.0));
    CHECK(a.sheen.x == Approx(closed_form).epsilon(1e-9));
    CHECK(a.diffuse.x == 0.0);
  }
  SECTION("GGX and GTR1 normalisation: integral of D(m) (n.m) dm = 1") {
    for (double roughness : roughness_values) {
      const double alpha = shaders_ref::ggx_alpha(roughness);
      const auto integral_of = [alpha](double (*ndf)(const glm::dvec3&, double)) {
        return shaders_ref::integrate_over_microfacet_normals(
            [&](const glm::dvec3& m) { return ndf(m, alpha) * m.z; }, alpha);
      };
      CAPTURE(roughness);
      CHECK(integral_of(shaders_ref::ggx_ndf) == Approx(1.0).epsilon(1e-9));
      // GTR1's log-uniform tail is slower to converge in GGX's stretched angle.
      CHECK(integral_of(shaders_ref::gtr1_ndf) == Approx(1.0).epsilon(1e-8));
    }
  }
  SECTION("Clearcoat albedo: half-vector and spherical quadratures agree") {
    shaders_ref::PrincipledParams lacquer;
    lacquer.base_color = glm::dvec3(0.0);
    lacquer.specular = 0.0;
    lacquer.clearcoat = 1.0;
    for (double roughness : {0.03, 0.1, 0.5, 1.0}) {
      for (double cos_o : {1.0, 0.7, 0.02}) {
        lacquer.clearcoat_roughness = roughness;
        const double a = shaders_ref::ggx_alpha(roughness);
        const glm::dvec3 wo = direction_with_cosine(cos_o);
        const double spherical = shaders_ref::integrate_over_sphere(
            [&](const glm::dvec3& wi) { return shaders_ref::clearcoat_brdf(lacquer, wo, wi).x * wi.z; },
            {-wo.x, -wo.y, wo.z}, 2.0 * a * cos_o);
        const shaders_ref::LobeAlbedos albedos = shaders_ref::lobe_albedos(lacquer, wo);
        CAPTURE(roughness, cos_o);
        // integrate_over_sphere's absolute accuracy, 1e-4 of these albedos.
        CHECK(albedos.clearcoat.x == Approx(spherical).margin(1e-6));
        // A quarter of a dielectric's reflectance, at most.
        CHECK(albedos.clearcoat.x <= 0.25);
        CHECK(albedos.diffuse.x + albedos.specular.x == 0.0);
      }
    }
  }
  SECTION(
      "Visible normals: integral of G1(wo) max(0, wo.m) D(m) / cos_o dm = 1 (Heitz 2018, eq. 1)") {
    for (double roughness : roughness_values) {
      for (double cos_o : cos_values) {
        const double alpha = shaders_ref::ggx_alpha(roughness);
        const glm::dvec3 wo = direction_with_cosine(cos_o);
        const double integral = shaders_ref::integrate_over_microfacet_normals(
            [&](const glm::dvec3& m) {
              return shaders_ref::ggx_smith_g1(wo, alpha) * std::max(0.0, glm::dot(wo, m)) *
                     shaders_ref::ggx_ndf(m, alpha) / wo.z;
            },
            alpha);
        CAPTURE(roughness, cos_o);
        CHECK(integral == Approx(1.0).epsilon(1e-7));
      }
    }
  }
  SECTION("GGX albedo at alpha 1 with F = 1 is 2 (1 - ln 2) / (1 + cos_o)") {
    // alpha = 1: D = 1/pi, G1(w) = 2 cos / (1 + cos), so with F = 1 (metallic 1, base 1)
    // a = G1(wo) / (4 pi cos_o) int G1(wi) dwi
    //   = 1 / (2 pi (1 + cos_o)) 2 pi int_0^1 2c / (1 + c) dc = 2 (1 - ln 2) / (1 + cos_o).
    shaders_ref::PrincipledParams mirror_white;
    mirror_white.base_color = glm::dvec3(1.0);
    mirror_white.metallic = 1.0;
    mirror_white.roughness = 1.0;
    for (double cos_o : cos_values) {
      CAPTURE(cos_o);
      const shaders_ref::LobeAlbedos a =
          shaders_ref::lobe_albedos(mirror_white, direction_with_cosine(cos_o));
      CHECK(a.specular.x == Approx(2.0 * (1.0 - std::log(2.0)) / (1.0 + cos_o)).epsilon(1e-8));
      CHECK(a.diffuse.x == 0.0);
    }
  }
  SECTION("Specular albedo: half-vector and spherical quadratures agree") {
    // lobe_albedos integrates over half vectors with the horizon in closed form;
    // integrate_over_sphere knows nothing of the lobe but where its peak is. Their agreement at
    // low roughness and grazing incidence checks the half-vector parametrisation where no closed
    // form exists (integrate_over_sphere is good to ~1e-6 absolute).
    shaders_ref::PrincipledParams metal;
    metal.base_color = glm::dvec3(0.9);
    metal.metallic = 1.0;
    for (double roughness : {0.02, 0.1, 0.5}) {
      for (double cos_o : {0.7, 0.02}) {
        metal.roughness = roughness;
        const double alpha = shaders_ref::ggx_alpha(roughness);
        const glm::dvec3 wo = direction_with_cosine(cos_o);
        const double spherical = shaders_ref::integrate_over_sphere(
            [&](const glm::dvec3& wi) {
              return shaders_ref::specular_brdf(metal, wo, wi).x * wi.z;
            },
            {-wo.x, -wo.y, wo.z}, 2.0 * alpha * cos_o);
        CAPTURE(roughness, cos_o);
        CHECK(shaders_ref::lobe_albedos(metal, wo).specular.x == Approx(spherical).epsilon(1e-5));
      }
    }
  }
  SECTION("Single-scatter GGX with F = 1 loses energy but never gains it") {
    shaders_ref::PrincipledParams mirror_white;
    mirror_white.base_color = glm::dvec3(1.0);
    mirror_white.metallic = 1.0;
    for (double roughness : roughness_values) {
      for (double cos_o : cos_values) {
        mirror_white.roughness = roughness;
        CAPTURE(roughness, cos_o);
        const double a =
            shaders_ref::directional_albedo(mirror_white, direction_with_cosine(cos_o)).x;
        CHECK(a <= 1.0);
        CHECK(a > 0.25);
      }
    }
  }
  SECTION("Dielectric Fresnel from the s- and p-amplitudes") {
    CHECK(shaders_ref::principled_specular_ior(0.5) == Approx(1.5).epsilon(1e-15));
    CHECK(shaders_ref::dielectric_fresnel(1.0, 1.5) == Approx(0.04).epsilon(1e-14));
    CHECK(shaders_ref::dielectric_fresnel(0.0, 1.5) == Approx(1.0).epsilon(1e-14));
    // At Brewster's angle (tan theta = eta) r_p = 0 and r_s = (1 - eta^2) / (1 + eta^2).
    const double eta = 1.5;
    const double cos_brewster = 1.0 / std::sqrt(1.0 + eta * eta);
    const double r_s = (1.0 - eta * eta) / (1.0 + eta * eta);
    CHECK(shaders_ref::dielectric_fresnel(cos_brewster, eta) ==
          Approx(0.5 * r_s * r_s).epsilon(1e-12));
    // Interpolated Fresnel: cspec0 at normal incidence, 1 at grazing.
    shaders_ref::PrincipledParams p;
    p.base_color = {0.9, 0.5, 0.1};
    p.metallic = 0.3;
    p.specular_tint = 0.4;
    const glm::dvec3 cspec0 = shaders_ref::specular_color_at_normal_incidence(p);
    for (int k = 0; k < 3; ++k) {
      CHECK(shaders_ref::interpolated_fresnel(p, 1.0)[k] == Approx(cspec0[k]).epsilon(1e-14));
      CHECK(shaders_ref::interpolated_fresnel(p, 0.0)[k] == Approx(1.0).epsilon(1e-14));
    }
  }
}

TEST_CASE("Fast BSDF eval agrees with the double-precision reference", "[render]") {
  // Tolerances from float precision: a float evaluation of these formulas carries a few 1e-7
  // relative, so 1e-5 relative leaves a wide margin. Three terms cover inputs where float loses
  // more: (1) the interpolated Fresnel's F(cos) - F0 cancels near normal incidence to ~1e-7
  // absolute, 1e-6 times the BRDF without Fresnel (F = 1: metallic 1, base 1); (2) the Fresnel
  // argument wi.h of a half vector h = normalize(wo + wi) has a relative error ~ eps / |wo + wi|,
  // which matters where wo and wi are nearly opposite (cos_h small): 1e-6 / cos_h relative;
  // (3) the lobe's sensitivity to the rounding of the directions themselves
  // (ggx_direction_condition), large in the peak of a smooth surface: 1.5e-4 relative at
  // roughness 0.02. Half of the inputs put wi in the specular peak, where D is steepest.
  UniformFloats rng(0x5eed1000);
  constexpr int kInputs = 10000;
  int diffuse_failures = 0;
  int specular_failures = 0;
  int total_failures = 0;
  for (int n = 0; n < kInputs; ++n) {
    const PrincipledInputs in = random_material(rng, 0.02f, 1.0f);
    const glm::vec3 wo = random_upper_direction(rng);
    // Odd inputs aim at the specular peak, every fourth at the clearcoat's.
    const float peak_roughness =
        in.scalar(n % 4 == 1 ? MaterialParameter::ClearcoatRoughness : MaterialParameter::Roughness);
    const glm::vec3 wi =
        n % 2 ? direction_near_peak(wo, peak_roughness * peak_roughness, rng) : random_upper_direction(rng);
    const LobeMixture bsdf = principled_bsdf(in, wo);
    float pdf = 0.0f;
    const glm::vec3 diffuse = diffuse_value(bsdf, wi) / wi.z;
    const glm::vec3 specular = specular_value(bsdf, wi) / wi.z;
    const glm::vec3 total = bsdf.eval(wi, &pdf) / wi.z;

    const shaders_ref::PrincipledParams p = reference_params(in);
    const glm::dvec3 wo_d = glm::normalize(glm::dvec3(wo));
    const glm::dvec3 wi_d = glm::normalize(glm::dvec3(wi));
    // The sheen and velvet lobes are diffuse ones (Cycles labels them so): the diffuse flag
    // selects all three.
    const glm::dvec3 sheen_ref = shaders_ref::sheen_brdf(p, wo_d, wi_d);
    const glm::dvec3 velvet_ref = shaders_ref::velvet_brdf(p, wo_d, wi_d);
    const glm::dvec3 diffuse_ref = shaders_ref::diffuse_brdf(p, wo_d, wi_d) + sheen_ref + velvet_ref;
    const double velvet_error = velvet_condition(in, wo_d, wi_d);
    // The glossy flag selects the specular lobe, the glass's reflection (the same GGX lobe) and
    // the clearcoat.
    const glm::dvec3 clearcoat_ref = shaders_ref::clearcoat_brdf(p, wo_d, wi_d);
    const glm::dvec3 specular_ref =
        shaders_ref::specular_brdf(p, wo_d, wi_d) + shaders_ref::glass_reflection_brdf(p, wo_d, wi_d) + clearcoat_ref;
    const glm::dvec3 total_ref = shaders_ref::principled_brdf(p, wo_d, wi_d);
    shaders_ref::PrincipledParams fresnel_one = p;
    fresnel_one.base_color = glm::dvec3(1.0);
    fresnel_one.metallic = 1.0;
    const double specular_without_fresnel = shaders_ref::specular_brdf(fresnel_one, wo_d, wi_d).x;
    const double cos_h = glm::length(wo_d + wi_d) / 2.0;
    const double conditioning =
        ggx_direction_condition(wo_d, wi_d, shaders_ref::ggx_alpha(p.roughness));
    // GTR1's ln D changes at most half as fast as GGX's of the same width (its denominator is
    // squared in GGX), so the GGX condition bounds the clearcoat's.
    const double clearcoat_conditioning =
        ggx_direction_condition(wo_d, wi_d, shaders_ref::ggx_alpha(p.clearcoat_roughness));

    for (int k = 0; k < 3; ++k) {
      const double specular_tolerance = (1e-5 + 1e-6 / cos_h + conditioning) * (specular_ref[k] - clearcoat_ref[k]) +
                                        1e-6 * specular_without_fresnel +
                                        (1e-5 + 1e-6 / cos_h + clearcoat_conditioning) * clearcoat_ref[k];
      // The sheen's (1 - wi.h)^5 shares the half vector's error (term 2 above), absolute near wi.h = 1;
      // the velvet's D(h) is as sensitive as velvet_condition says.
      const double diffuse_tolerance = 1e-5 * diffuse_ref[k] + 1e-6 / cos_h * sheen_ref[k] + 1e-7 * p.sheen +
                                       (1e-6 / cos_h + velvet_error) * velvet_ref[k] + 1e-12;
      const bool diffuse_ok = std::abs(diffuse[k] - diffuse_ref[k]) <= diffuse_tolerance;
      const bool specular_ok = std::abs(specular[k] - specular_ref[k]) <= specular_tolerance;
      const bool total_ok =
          std::abs(total[k] - total_ref[k]) <= diffuse_tolerance + specular_tolerance;
      diffuse_failures += !diffuse_ok;
      specular_failures += !specular_ok;
      total_failures += !total_ok;
      if (!(diffuse_ok && specular_ok && total_ok)) {
        INFO("input " << n << " channel " << k << ": base (" << in.color(MaterialParameter::BaseColor).x << ", "
                      << in.color(MaterialParameter::BaseColor).y << ", " << in.color(MaterialParameter::BaseColor).z << "), metallic " << in.scalar(MaterialParameter::Metallic)
                      << ", roughness " << in.scalar(MaterialParameter::Roughness) << ", specular " << in.scalar(MaterialParameter::Specular) << ", tint "
                      << in.scalar(MaterialParameter::SpecularTint) << ", sheen "
                      << in.scalar(MaterialParameter::Sheen) << " tint " << in.scalar(MaterialParameter::SheenTint)
                      << ", clearcoat " << in.scalar(MaterialParameter::Clearcoat) << " roughness "
                      << in.scalar(MaterialParameter::ClearcoatRoughness) << ", "
                      << (in.diffuse_model == DiffuseModel::Lambert ? "Lambert" : "principled")
                      << "; cos_o " << wo.z << ", cos_i " << wi.z << ", cos_h " << cos_h);
        INFO("diffuse " << diffuse[k] << " vs " << diffuse_ref[k] << "; specular " << specular[k]
                        << " vs " << specular_ref[k] << " (rel. "
                        << (specular[k] - specular_ref[k]) / specular_ref[k] << "); total "
                        << total[k] << " vs " << total_ref[k]);
        // Report the first few disagreements in full; the counts below summarise the rest.
        if (diffuse_failures + specular_failures + total_failures <= 10) FAIL_CHECK("mismatch");
      }
    }
  }
  CHECK(diffuse_failures == 0);
  CHECK(specular_failures == 0);
  CHECK(total_failures == 0);
}

TEST_CASE("Singular mirror lobe: sample weight is F(cos_o) over its selection probability",
          "[render]") {
  // Below roughness (1e-7)^(1/4) = 0.01778 (alpha^2 <= 1e-7) the GGX lobe is a mirror
  // (Cycles' "singular" case): the sampled direction is the mirror image of wo, and the weight is
  // the Fresnel reflectance F(wo.n) divided by the probability of having picked the lobe,
  // avg(F(cos_o)) / (avg((1 - metallic) base) + avg(F(cos_o))).
  UniformFloats rng(0x5eed1100);
  int checked = 0;
  for (int n = 0; n < 5000; ++n) {
    PrincipledInputs in = random_material(rng, 0.0f, 0.0177f);
    in.set(MaterialParameter::Sheen, 0.0f);  // the two lobes of the formula above
    in.set(MaterialParameter::Clearcoat, 0.0f);
    in.set(MaterialParameter::Transmission, 0.0f);
    in.set(MaterialParameter::VelvetColor, glm::vec3(0.0f));
    if (n % 4 == 0) in.set(MaterialParameter::Metallic, 1.0f);  // no diffuse lobe: the weight is F itself
    const glm::vec3 wo = random_upper_direction(rng);
    const LobeMixture bsdf = principled_bsdf(in, wo);
    if (!any(bsdf.flags() & (matrender::BxDFFlags::Glossy | matrender::BxDFFlags::Specular))) continue;

    const shaders_ref::PrincipledParams p = reference_params(in);
    const glm::dvec3 fresnel = shaders_ref::interpolated_fresnel(p, static_cast<double>(wo.z));
    const double diffuse_weight = average((1.0 - p.metallic) * p.base_color);
    const double specular_probability = average(fresnel) / (diffuse_weight + average(fresnel));
    if (specular_probability < 1e-6) continue;  // the lobe is (almost) never picked

    BsdfSample s;
    REQUIRE(bsdf.sample(1.0f - 0x1p-24f, {rng.next(), rng.next()}, &s));
    INFO("metallic " << in.scalar(MaterialParameter::Metallic) << ", specular " << in.scalar(MaterialParameter::Specular) << ", roughness "
                     << in.scalar(MaterialParameter::Roughness) << ", cos_o " << wo.z);
    CHECK(matrender::is_specular(s.flags));
    CHECK(!matrender::is_diffuse(s.flags));
    CHECK(s.pdf == 0.0f);
    CHECK(s.wi.x == -wo.x);
    CHECK(s.wi.y == -wo.y);
    CHECK(s.wi.z == wo.z);
    for (int k = 0; k < 3; ++k)
      CHECK(s.weight[k] * specular_probability == Approx(fresnel[k]).epsilon(1e-5).margin(1e-7));
    // A delta lobe has no density to evaluate.
    CHECK(specular_value(bsdf, s.wi) == glm::vec3(0.0f));
    ++checked;
  }
  CHECK(checked > 3000);
}

TEST_CASE("Singular clearcoat: sample weight is 0.25 clearcoat F(cos_o; 1.5) over its selection probability",
          "[render]") {
  // Clearcoat roughness below (1e-7)^(1/4) makes the lacquer a mirror, as Cycles' singular GGX.
  // With no other lobe (black base, no specular) it is picked every time.
  UniformFloats rng(0x5eed1200);
  for (int n = 0; n < 2000; ++n) {
    PrincipledInputs in;
    in.set(MaterialParameter::BaseColor, glm::vec3(0.0f));
    in.set(MaterialParameter::Specular, 0.0f);
    const float clearcoat = 0.01f + 0.99f * rng.next();
    in.set(MaterialParameter::Clearcoat, clearcoat);
    in.set(MaterialParameter::ClearcoatRoughness, 0.0177f * rng.next());
    const glm::vec3 wo = random_upper_direction(rng);
    const LobeMixture bsdf = principled_bsdf(in, wo);
    BsdfSample s;
    REQUIRE(bsdf.sample(rng.next(), {rng.next(), rng.next()}, &s));
    CHECK(matrender::is_specular(s.flags));
    CHECK(s.wi == glm::vec3(-wo.x, -wo.y, wo.z));
    const double expected = 0.25 * clearcoat * shaders_ref::dielectric_fresnel(wo.z, 1.5);
    CHECK(s.weight.x == Approx(expected).epsilon(1e-5));
  }
}

TEST_CASE("Fast glass refraction agrees with the double-precision reference", "[render]") {
  // Below the surface only the glass refraction answers. Half of the directions lie in its peak
  // (wo refracted through a microfacet within three widths of the normal). Tolerance: 1e-5
  // relative for float, plus the lobe's sensitivity to the rounding of the directions, whose
  // generalised half vector is ill-conditioned where wo + eta wi is short.
  UniformFloats rng(0x5eed1300);
  int failures = 0;
  int nonzero = 0;
  for (int n = 0; n < 20000; ++n) {
    PrincipledInputs in = random_material(rng, 0.02f, 1.0f);
    in.set(MaterialParameter::Transmission, rng.next() < 0.2f ? 1.0f : rng.next());
    in.set(MaterialParameter::TransmissionRoughness, rng.next() < 0.5f ? 0.0f : rng.next());
    in.set(MaterialParameter::Ior, 1.0f + 1.5f * rng.next());
    const bool front_face = rng.next() < 0.5f;
    const glm::vec3 wo = random_upper_direction(rng);
    shaders_ref::PrincipledParams p = reference_params(in);
    p.front_face = front_face;
    const double eta = shaders_ref::glass_eta(p);
    const double roughness = 1.0 - (1.0 - p.roughness) * (1.0 - p.transmission_roughness);
    const double alpha = shaders_ref::ggx_alpha(roughness);
    glm::vec3 wi = random_upper_direction(rng);
    wi.z = -wi.z;
    if (n % 2) {
      const float tan_m = 3.0f * static_cast<float>(alpha) * rng.next();
      const float phi = 2.0f * static_cast<float>(kPi) * rng.next();
      const glm::vec3 m = glm::normalize(glm::vec3(tan_m * std::cos(phi), tan_m * std::sin(phi), 1.0f));
      glm::vec3 refracted;
      if (matrender::refract_about(wo, m, static_cast<float>(eta), &refracted) && refracted.z < 0.0f)
        wi = glm::normalize(refracted);
    }
    const LobeMixture bsdf = principled_bsdf(in, wo, matrender::ClearcoatEstimator::Integral, front_face);
    float pdf;
    const glm::vec3 value = bsdf.eval(wi, matrender::BxDFFlags::Transmission, &pdf) / std::abs(wi.z);
    const glm::dvec3 wo_d = glm::normalize(glm::dvec3(wo));
    const glm::dvec3 wi_d = glm::normalize(glm::dvec3(wi));
    const glm::dvec3 reference = shaders_ref::glass_refraction_btdf(p, wo_d, wi_d);
    if (reference.x + reference.y + reference.z > 0.0) ++nonzero;
    // ln D(m) changes at 4 tan / (alpha^2 + tan^2) per radian of m (as in ggx_direction_condition),
    // and m = (wo + eta wi) / |wo + eta wi| turns (1 + eta) / |wo + eta wi| times as much as the
    // directions; G1 adds ~1 / cos per radian at grazing. Relative errors per radian, times the
    // directions' 2^-22.
    const glm::dvec3 m = glm::normalize(-(wo_d + eta * wi_d));
    const double tan_m = std::sqrt(shaders_ref::tan2_theta(m));
    const double ndf_slope = 4.0 * tan_m / (alpha * alpha + tan_m * tan_m);
    const double turn = (1.0 + eta) / std::max(glm::length(wo_d + eta * wi_d), 1e-6);
    // The cosines with m lose their relative digits toward 0, and (wo.m + eta wi.m)^2 toward a
    // cancelling sum.
    const double wo_m = std::abs(glm::dot(wo_d, m)), wi_m = std::abs(glm::dot(wi_d, m));
    const double sum = std::abs(wo_m - eta * wi_m);
    const double cosines = 1.0 / std::max(wo_m, 1e-6) + 1.0 / std::max(wi_m, 1e-6) +
                           2.0 * (wo_m + eta * wi_m) / std::max(sum, 1e-6);
    // The weight's 1 - F(cos_o) near the critical angle, where F's g = sqrt(eta^2 - 1 + cos^2)
    // has an infinite slope: float rounding of g^2 moves it by eps (eta^2 + 1) / g^2.
    const double g2 = eta * eta - 1.0 + wo_d.z * wo_d.z;
    const double critical = g2 > 0.0 ? (eta * eta + 1.0) / std::max(g2, 1e-9) : 0.0;
    const double conditioning =
        0x1p-22 * (ndf_slope * turn + turn * cosines + 1.0 / wo_d.z + 1.0 / std::abs(wi_d.z) + critical);
    for (int k = 0; k < 3; ++k) {
      const double tolerance = (1e-5 + conditioning) * reference[k] + 1e-9;
      if (std::abs(value[k] - reference[k]) <= tolerance) continue;
      ++failures;
      INFO("input " << n << ": transmission " << p.transmission << " ior " << p.ior
                    << (front_face ? " entering" : " leaving") << ", roughness " << roughness << ", cos_o " << wo.z
                    << ", cos_i " << wi.z << "; fast " << value[k] << ", reference " << reference[k] << " (rel. "
                    << (value[k] - reference[k]) / reference[k] << ")");
      if (failures <= 10) FAIL_CHECK("mismatch");
    }
  }
  CHECK(failures == 0);
  // Random pairs that no microfacet refracts into each other, or closures below the cutoff, give 0.
  CHECK(nonzero > 5000);
}
