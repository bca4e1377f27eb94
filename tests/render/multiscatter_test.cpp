// Multiscatter GGX (Cycles 3.4's random walk on the microsurface): a white rough metal keeps its
// energy where single scattering loses it, the stochastic evaluation is reciprocal walk for walk,
// its mean over the hemisphere is the albedo its samples carry, and renders stay finite.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>

#include "bsdf/multiscatter_ggx_lobe.h"
#include "bsdf/principled.h"
#include "matbase/pi.h"
#include "matrender/camera.h"
#include "matrender/render.h"
#include "matrender/scene.h"
#include "test_scenes.h"
#include "uniform_floats.h"

using namespace matrender;

namespace {

// F = 1 at every angle: a white conductor, the white furnace of the Heitz et al. 2016 paper.
const InterpolatedFresnel kWhite(glm::vec3(1.0f), 1.5f);

glm::vec3 view_at(float cos_o) { return {std::sqrt(1.0f - cos_o * cos_o), 0.0f, cos_o}; }

struct Mean {
  double mean = 0.0, standard_error = 0.0;
};

template <class Draw>
Mean mean_of(int n, Draw&& draw) {
  double sum = 0.0, sum2 = 0.0;
  for (int i = 0; i < n; ++i) {
    const double v = draw(i);
    sum += v;
    sum2 += v * v;
  }
  const double mean = sum / n;
  return {mean, std::sqrt(std::max(0.0, sum2 / n - mean * mean) / (n - 1))};
}

// The directional albedo: the mean weight of the lobe's samples (0 for a failed one).
Mean sampled_albedo(float alpha, float cos_o, bool multiscatter) {
  UniformFloats rng(31);
  return mean_of(200000, [&](int i) {
    LobeMixture lobes;
    if (multiscatter)
      lobes.add(MultiscatterGgxLobe(1.0f, kWhite, alpha, view_at(cos_o), static_cast<uint32_t>(i) * 2654435761u));
    else
      lobes.add(GgxReflectionLobe(1.0f, kWhite, alpha, false, view_at(cos_o)));
    lobes.finish();
    BsdfSample sample;
    if (!lobes.sample(glm::vec2(rng.next(), rng.next()), &sample)) return 0.0;
    return static_cast<double>(sample.weight.x);
  });
}

}  // namespace

TEST_CASE("Multiscatter GGX keeps a white rough metal's energy that single scattering loses", "[render]") {
  for (const float roughness : {0.5f, 1.0f}) {
    for (const float cos_o : {1.0f, 0.5f, 0.15f}) {
      const float alpha = roughness * roughness;
      const Mean single = sampled_albedo(alpha, cos_o, false), multi = sampled_albedo(alpha, cos_o, true);
      INFO("roughness " << roughness << " cos_o " << cos_o << ": single " << single.mean << ", multiscatter "
                        << multi.mean << " +- " << multi.standard_error);
      // Ten bounces leave at most a few tenths of a per cent inside (the paper's figure 15), and
      // the walk's weights never exceed 1 for a white surface.
      CHECK(multi.mean <= 1.0 + 4.0 * multi.standard_error);
      CHECK(multi.mean >= 0.985);
      CHECK(multi.mean > single.mean + (roughness == 1.0f ? 0.2 : 0.03));
    }
  }
}

TEST_CASE("Multiscatter GGX evaluates reciprocally walk for walk", "[render]") {
  // The walk starts from the shallower direction whichever is the viewer's, so with one seed
  // f(wo, wi) = f(wi, wo): eval gives f cos(theta_i).
  UniformFloats rng(5);
  const glm::vec3 tint(0.9f, 0.6f, 0.3f);
  const InterpolatedFresnel gold(tint, 1.5f);
  for (int i = 0; i < 200; ++i) {
    const glm::vec3 a = random_upper_direction(rng), b = random_upper_direction(rng);
    const uint32_t seed = 1000u + static_cast<uint32_t>(i);
    float pdf_ab, pdf_ba;
    const glm::vec3 f_ab = MultiscatterGgxLobe(1.0f, gold, 0.4f, a, seed).eval(b, &pdf_ab) / b.z;
    const glm::vec3 f_ba = MultiscatterGgxLobe(1.0f, gold, 0.4f, b, seed).eval(a, &pdf_ba) / a.z;
    for (int c = 0; c < 3; ++c) CHECK(f_ab[c] == Approx(f_ba[c]).epsilon(1e-4).margin(1e-7));
  }
}

TEST_CASE("Multiscatter GGX's evaluation integrates to the albedo its samples carry", "[render]") {
  // Two independent estimators of one directional albedo: uniform hemisphere directions times
  // the stochastic eval, and the walk's own samples.
  for (const float alpha : {0.16f, 0.6f, 1.0f}) {
    for (const float cos_o : {0.9f, 0.3f}) {
      const glm::vec3 wo = view_at(cos_o);
      const InterpolatedFresnel copper(glm::vec3(0.95f, 0.64f, 0.54f), 1.5f);
      UniformFloats rng(77);
      const Mean by_eval = mean_of(400000, [&](int i) {
        const glm::vec3 wi = random_upper_direction(rng);
        float pdf;
        const glm::vec3 f = MultiscatterGgxLobe(1.0f, copper, alpha, wo, static_cast<uint32_t>(i) * 747796405u).eval(wi, &pdf);
        return static_cast<double>(f.y) * 2.0 * matbase::kPi;
      });
      const Mean by_sample = mean_of(400000, [&](int i) {
        LobeMixture lobes;
        lobes.add(MultiscatterGgxLobe(1.0f, copper, alpha, wo, static_cast<uint32_t>(i) * 2891336453u + 7u));
        lobes.finish();
        BsdfSample s;
        if (!lobes.sample(glm::vec2(0.5f), &s)) return 0.0;
        return static_cast<double>(s.weight.y);
      });
      INFO("alpha " << alpha << " cos_o " << cos_o << ": by eval " << by_eval.mean << " +- " << by_eval.standard_error
                    << ", by sample " << by_sample.mean << " +- " << by_sample.standard_error);
      CHECK(std::abs(by_eval.mean - by_sample.mean) <= 4.0 * std::hypot(by_eval.standard_error, by_sample.standard_error));
    }
  }
}

TEST_CASE("Cycles 3.4's walk, kept for parity, loses energy where the exact walk keeps it", "[render]") {
  // Its evaluation walks from the shallower direction and puts a rising ray that meets the
  // surface again at the top: seen from above, a white metal of alpha 1 reflects less than the
  // exact walk's 1 (which its samples, unaffected, still carry).
  const glm::vec3 wo = view_at(0.9f);
  const auto albedo_by_eval = [&](MultiscatterWalk walk) {
    UniformFloats rng(78);
    return mean_of(200000, [&](int i) {
      const glm::vec3 wi = random_upper_direction(rng);
      float pdf;
      return static_cast<double>(
                 MultiscatterGgxLobe(1.0f, kWhite, 1.0f, wo, static_cast<uint32_t>(i) * 747796405u, walk).eval(wi, &pdf).x) *
             2.0 * matbase::kPi;
    });
  };
  const Mean exact = albedo_by_eval(MultiscatterWalk::Exact), cycles = albedo_by_eval(MultiscatterWalk::Cycles34);
  INFO("exact " << exact.mean << " +- " << exact.standard_error << ", Cycles 3.4 " << cycles.mean << " +- "
                << cycles.standard_error);
  CHECK(std::abs(exact.mean - 1.0) <= 4.0 * exact.standard_error + 2e-3);
  CHECK(cycles.mean < exact.mean - 20.0 * exact.standard_error);
}

TEST_CASE("A white multiscatter metal sphere in a white furnace shows nearly 1", "[render]") {
  Material metal;
  metal.set(MaterialParameter::BaseColor, glm::vec3(1.0f));
  metal.set(MaterialParameter::Metallic, 1.0f);
  metal.set(MaterialParameter::Roughness, 1.0f);
  double single = 0.0, multi = 0.0;
  for (const SpecularDistribution distribution : {SpecularDistribution::GGX, SpecularDistribution::MultiscatterGGX}) {
    metal.distribution = distribution;
    Scene scene;
    scene.add_mesh(test_scenes::uv_sphere(0.5, 32), {scene.add_material(metal)});
    scene.set_background(glm::vec3(1.0f));
    RenderSettings settings;
    settings.samples_per_pixel = 64;
    settings.aovs = 0;
    FrameBuffers frame;
    REQUIRE(render(scene, Camera::look_at({0, -3, 0}, {0, 0, 0}, {0, 0, 1}, 0.1, 16, 16), settings, frame)
                .discarded_samples == 0);
    CHECK(test_scenes::all_finite(frame.color));
    (distribution == SpecularDistribution::GGX ? single : multi) = test_scenes::channel_statistics(frame, 0).mean;
  }
  INFO("single " << single << ", multiscatter " << multi);
  CHECK(multi > 0.97);
  CHECK(multi > single + 0.1);
}
