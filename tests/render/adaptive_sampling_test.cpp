// Adaptive sampling as Cycles 3.4 does it: its schedule and neighbour rule against the rules as
// Cycles states them, the two halves of a pixel's samples, and renders: samples go where the
// noise is, the image is the same for any thread count, and it converges to the fixed-sample image.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <set>
#include <vector>

#include "film/adaptive_sampling.h"
#include "matrender/camera.h"
#include "matrender/render.h"
#include "matrender/scene.h"
#include "sampling/pixel_sampler.h"
#include "test_scenes.h"

using namespace matrender;

TEST_CASE("Adaptive sampling's automatic minimum is Cycles' table", "[render]") {
  // Cycles' own comment in Integrator::get_adaptive_sampling: 0.1 -> 32, 0.01 -> 64, 0.001 -> 128.
  CHECK(AdaptiveSampling::from_settings(0.1, 0)->min_samples() == 32);
  CHECK(AdaptiveSampling::from_settings(0.01, 0)->min_samples() == 64);
  CHECK(AdaptiveSampling::from_settings(0.001, 0)->min_samples() == 128);
  CHECK(AdaptiveSampling::from_settings(0.5, 0)->min_samples() == 20);  // ceil(16 / 0.5^0.3) = ceil(19.7)
  // A given minimum below 4 is raised to 4; the threshold is scaled by 5.
  CHECK(AdaptiveSampling::from_settings(0.01, 1)->min_samples() == 4);
  CHECK(AdaptiveSampling::from_settings(0.01, 100)->min_samples() == 100);
  CHECK(AdaptiveSampling::from_settings(0.01, 0)->error_bound() == Approx(0.05f));
  CHECK_FALSE(AdaptiveSampling::from_settings(0.0, 64).has_value());
}

TEST_CASE("Pixels are checked after the samples Cycles checks after", "[render]") {
  // Cycles' need_filter(s): s > min_samples and s mod 16 = 15, s the 0-based index of the sample
  // just taken; a check after index s comes at a count of s + 1 samples.
  for (int min_samples = 4; min_samples < 300; ++min_samples) {
    const AdaptiveSampling adaptive = *AdaptiveSampling::from_settings(0.01, min_samples);
    std::vector<uint32_t> cycles_checks;
    for (uint32_t s = 0; cycles_checks.size() < 4; ++s)
      if (static_cast<int>(s) > min_samples && (s & 15u) == 15u) cycles_checks.push_back(s + 1);
    std::vector<uint32_t> ours{adaptive.next_check(0)};
    while (ours.size() < 4) ours.push_back(adaptive.next_check(ours.back()));
    INFO("min samples " << min_samples);
    CHECK(ours == cycles_checks);
  }
  const RenderSettings settings = [] {
    RenderSettings s;
    s.samples_per_pixel = 512;
    s.noise_threshold = 0.01;
    return s;
  }();
  CHECK(fewest_samples_per_pixel(settings) == 80);  // min 64: the first check after index 79
  RenderSettings few = settings;
  few.samples_per_pixel = 50;
  CHECK(fewest_samples_per_pixel(few) == 50);
  few.noise_threshold = 0.0;
  CHECK(fewest_samples_per_pixel(few) == 50);
}

TEST_CASE("A pixel still sampling keeps its 3 x 3 neighbourhood sampling", "[render]") {
  std::mt19937 random(5);
  for (int trial = 0; trial < 200; ++trial) {
    const int w = 1 + static_cast<int>(random() % 9), h = 1 + static_cast<int>(random() % 7);
    std::vector<uint8_t> converged(static_cast<size_t>(w * h));
    for (uint8_t& c : converged) c = (random() % 5) != 0;
    std::vector<uint8_t> expected = converged;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int nx = x + dx, ny = y + dy;
            if (nx >= 0 && nx < w && ny >= 0 && ny < h && converged[static_cast<size_t>(ny * w + nx)] == 0)
              expected[static_cast<size_t>(y * w + x)] = 0;
          }
    keep_neighbours_sampling(converged, w, h);
    REQUIRE(converged == expected);
  }
}

TEST_CASE("The convergence test is Cycles' relative error", "[render]") {
  // 100 samples summing to I = (50, 50, 50) with the second half's twice-sum A = (56, 50, 50):
  // error = 6 / 100 / (1e-4 + sqrt(150 / 100)) = 0.04899.
  const glm::dvec3 sum(50.0), second(28.0, 25.0, 25.0);
  CHECK(pixel_converged(sum, second, 100, 0.0490f));
  CHECK_FALSE(pixel_converged(sum, second, 100, 0.0489f));
  // Black pixels (nothing seen, every sample 0) have converged; a black sum with a non-zero half
  // cannot be, and a negative sum is no NaN.
  CHECK(pixel_converged(glm::dvec3(0.0), glm::dvec3(0.0), 16, 1e-6f));
  CHECK_FALSE(pixel_converged(glm::dvec3(-1.0), glm::dvec3(0.0), 16, 0.05f));
}

TEST_CASE("Each half of a pixel's samples is stratified along the pixel's x", "[render]") {
  // The first 2^m samples split into two halves of 2^(m-1), each of which has one point in every
  // stratum 2^-(m-1) wide along x (the pixel-filter pair's first coordinate), so each half alone
  // estimates the pixel nearly as well as the whole.
  for (uint32_t pixel : {0u, 9u, 77777u}) {
    const PixelSeeds seeds(pixel, 3);
    for (int m = 1; m <= 9; ++m) {
      const uint32_t n = 1u << m;
      std::set<uint32_t> strata_x[2];
      int count[2] = {0, 0};
      for (uint32_t i = 0; i < n; ++i) {
        const int half = in_second_estimate(shuffled_sobol_index(reverse_bits(i), seeds.pair(0))) ? 1 : 0;
        const glm::vec2 p = PixelSampler(seeds, i).get_2d(0);
        ++count[half];
        strata_x[half].insert(static_cast<uint32_t>(p.x * static_cast<float>(n / 2)));
      }
      INFO("pixel " << pixel << ", " << n << " samples");
      for (int half : {0, 1}) {
        CHECK(count[half] == static_cast<int>(n / 2));
        CHECK(strata_x[half].size() == n / 2);
      }
    }
  }
}

namespace {

// A grey sphere in front of a constant background, lit by a small lamp: the background has no
// noise at all, the sphere's lit side some, its penumbra and grazing edge the most.
Scene noisy_sphere_scene() {
  Scene scene;
  scene.add_mesh(test_scenes::uv_sphere(0.5, 24), {scene.add_material(test_scenes::lambert(0.7f))});
  RectLamp lamp;
  lamp.light_to_world = glm::dmat4(1.0);
  lamp.light_to_world[3] = glm::dvec4(0.6, -0.6, 1.2, 1.0);
  lamp.light_to_world[2] = glm::dvec4(glm::normalize(glm::dvec3(0.6, -0.6, 1.2)), 0.0);  // local +Z away from the sphere
  lamp.light_to_world[0] = glm::dvec4(glm::normalize(glm::cross(glm::dvec3(0, 0, 1), glm::dvec3(lamp.light_to_world[2]))), 0.0);
  lamp.light_to_world[1] = glm::dvec4(glm::cross(glm::dvec3(lamp.light_to_world[2]), glm::dvec3(lamp.light_to_world[0])), 0.0);
  lamp.size_x = lamp.size_y = 0.3;
  lamp.power = 40.0;
  scene.add_lamp(lamp);
  scene.add_lamp(PointLamp{glm::dvec3(-1.0, -0.5, 0.2), 5.0, glm::dvec3(1.0)});
  scene.set_background(glm::vec3(0.2f));
  return scene;
}

const Camera kSphereCamera = Camera::look_at({0.0, -2.5, 0.3}, {0, 0, 0}, {0, 0, 1}, 0.55, 40, 30);

FrameBuffers render_sphere(double noise_threshold, int spp, uint32_t seed, int threads = 0, int min_samples = 0) {
  Scene scene = noisy_sphere_scene();
  RenderSettings settings;
  settings.samples_per_pixel = spp;
  settings.noise_threshold = noise_threshold;
  settings.min_samples = min_samples;
  settings.seed = seed;
  settings.threads = threads;
  settings.aovs = AovSampleCount | AovAlpha | AovNormalWorld | parameter_aov(MaterialParameter::BaseColor);
  FrameBuffers frame;
  render(scene, kSphereCamera, settings, frame);
  return frame;
}

}  // namespace

TEST_CASE("Adaptive sampling spends its samples where the noise is", "[render]") {
  constexpr int kSpp = 512;
  const FrameBuffers frame = render_sphere(0.01, kSpp, 1);
  const uint32_t first_check = 80;  // threshold 0.01: 64 min samples
  std::vector<int32_t> background, sphere;
  for (int y = 0; y < frame.height; ++y)
    for (int x = 0; x < frame.width; ++x) {
      const size_t i = static_cast<size_t>(y * frame.width + x);
      const int32_t count = frame.sample_count[i];
      // Counts lie between the first check and spp; a pixel that stopped did so at a check.
      REQUIRE(count >= static_cast<int32_t>(first_check));
      REQUIRE(count <= kSpp);
      REQUIRE((count == kSpp || count % 16 == 0));
      // Pixels whose 3 x 3 neighbourhood is all background or all sphere.
      bool all_background = true, all_sphere = true;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = std::clamp(x + dx, 0, frame.width - 1), ny = std::clamp(y + dy, 0, frame.height - 1);
          const float coverage = frame.alpha[static_cast<size_t>(ny * frame.width + nx)];
          all_background &= coverage == 0.0f;
          all_sphere &= coverage == 1.0f;
        }
      if (all_background) background.push_back(count);
      if (all_sphere) sphere.push_back(count);
    }
  REQUIRE(background.size() > 300);
  REQUIRE(sphere.size() > 100);
  // The background is exact after one sample: it stops at the first check.
  for (const int32_t count : background) CHECK(count == static_cast<int32_t>(first_check));
  double sphere_mean = 0.0;
  for (const int32_t count : sphere) sphere_mean += count;
  sphere_mean /= static_cast<double>(sphere.size());
  CAPTURE(sphere_mean);
  CHECK(sphere_mean > 2.0 * first_check);
  // The AOVs are means over the samples each pixel took: the base colour stays exact.
  for (size_t i = 0; i < frame.alpha.size(); ++i)
    if (frame.alpha[i] == 1.0f) REQUIRE(frame.parameter(MaterialParameter::BaseColor)[3 * i] == Approx(0.7f).epsilon(1e-5));
}

TEST_CASE("Adaptive sampling converges to the fixed-sample image", "[render]") {
  // Two adaptive renders with different seeds measure each pixel's own noise; their mean must
  // differ from a 4096-sample render by no more than that noise allows (a pixel that stopped
  // early is still an unbiased mean of the samples it took).
  const FrameBuffers reference = render_sphere(0.0, 4096, 99);
  const FrameBuffers a = render_sphere(0.01, 1024, 1), b = render_sphere(0.01, 1024, 2);
  const size_t n = a.alpha.size();
  double difference = 0.0, variance = 0.0;
  for (size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) {
      const double mean = 0.5 * (a.color[3 * i + c] + b.color[3 * i + c]);
      const double half_gap = 0.5 * (a.color[3 * i + c] - b.color[3 * i + c]);
      difference += mean - reference.color[3 * i + c];
      variance += half_gap * half_gap;  // E[(a - b)^2 / 4] = var(a) / 2 = var(mean)
    }
  const double standard_error = std::sqrt(variance) / static_cast<double>(3 * n);
  difference /= static_cast<double>(3 * n);
  CAPTURE(difference, standard_error);
  CHECK(std::abs(difference) < 4.0 * standard_error + 2e-4);
  // And each pixel lands near its reference: the relative error the threshold asks for, with
  // room for the estimate's own noise.
  size_t far = 0;
  for (size_t i = 0; i < n; ++i) {
    const double ref = reference.color[3 * i] + reference.color[3 * i + 1] + reference.color[3 * i + 2];
    const double got = a.color[3 * i] + a.color[3 * i + 1] + a.color[3 * i + 2];
    if (std::abs(got - ref) > 0.05 * 4.0 * std::sqrt(ref) + 1e-3) ++far;
  }
  CHECK(far < n / 100);
}

TEST_CASE("Adaptive sampling gives the same image on one and two threads", "[render]") {
  const FrameBuffers one = render_sphere(0.02, 256, 7, 1), two = render_sphere(0.02, 256, 7, 2);
  CHECK(std::memcmp(one.color.data(), two.color.data(), one.color.size() * sizeof(float)) == 0);
  CHECK(one.sample_count == two.sample_count);
  CHECK(one.normal_world == two.normal_world);
}

TEST_CASE("Where nothing converges, adaptive sampling takes the fixed-sample image's very samples", "[render]") {
  // Rounds of 16 from min samples 4 on: at a threshold of 1e-9 only pixels without any noise stop
  // (the bare background, and sphere pixels lit only by the uniform background, whose every
  // sample is 0.7 x 0.2), and their mean is that same value; the others take the same samples,
  // summed in the same order as in one pass.
  const FrameBuffers fixed = render_sphere(0.0, 72, 4), rounds = render_sphere(1e-9, 72, 4, 0, 4);
  size_t full = 0, covered = 0, stopped = 0;
  for (size_t i = 0; i < rounds.alpha.size(); ++i) {
    const int32_t count = rounds.sample_count[i];
    INFO("pixel " << i << " took " << count);
    for (int c = 0; c < 3; ++c) REQUIRE(rounds.color[3 * i + c] == Approx(fixed.color[3 * i + c]).epsilon(1e-6));
    if (count == 72) {
      ++full;
      REQUIRE(std::memcmp(&rounds.color[3 * i], &fixed.color[3 * i], 3 * sizeof(float)) == 0);
      REQUIRE(std::memcmp(&rounds.normal_world[3 * i], &fixed.normal_world[3 * i], 3 * sizeof(float)) == 0);
      REQUIRE(rounds.alpha[i] == fixed.alpha[i]);
    } else {
      ++stopped;
    }
    if (rounds.alpha[i] > 0.0f) ++covered;
  }
  CHECK(stopped > 0);
  CHECK(full > covered * 9 / 10);
}

TEST_CASE("Adaptive sampling settings out of range are refused", "[render]") {
  Scene scene = noisy_sphere_scene();
  RenderSettings settings;
  FrameBuffers frame;
  settings.noise_threshold = -0.1;
  CHECK_THROWS_WITH(render(scene, kSphereCamera, settings, frame),
                    "render: noise_threshold: expected a number from 0 to 1, got -0.1");
  settings.noise_threshold = std::nan("");
  CHECK_THROWS_WITH(render(scene, kSphereCamera, settings, frame), Catch::StartsWith("render: noise_threshold:"));
  settings.noise_threshold = 0.01;
  settings.min_samples = -1;
  CHECK_THROWS_WITH(render(scene, kSphereCamera, settings, frame),
                    "render: min_samples: expected a whole number from 0 to 16,777,216, got -1");
}
