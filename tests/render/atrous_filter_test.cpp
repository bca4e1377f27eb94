// The denoiser on hard cases: frames built by hand where the truth is known (a boundary between
// two materials, a checker finer than a pixel, a nearly black object, hostile values) and
// renders against a high-sample reference (a diffuse ball, a glossy highlight).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "matrender/camera.h"
#include "matrender/atrous_filter.h"
#include "matrender/render.h"
#include "matrender/scene.h"
#include "test_scenes.h"

using namespace matrender;

namespace {

constexpr int kSide = 48;

// A frame of one flat surface facing the camera at depth 2 m, fully covered, every pixel's true
// colour `truth(x, y)` with Gaussian noise of standard deviation `noise` (its variance AOV says
// so), base colour `albedo(x, y)` and label `label(x, y)`.
template <class Truth, class Albedo, class Label>
FrameBuffers noisy_frame(Truth truth, Albedo albedo, Label label, float noise, uint32_t seed) {
  FrameBuffers frame;
  frame.resize(kSide, kSide, kAtrousFilterGuideAovs);
  frame.transparent_background = true;
  std::mt19937 random(seed);
  std::normal_distribution<float> gaussian(0.0f, noise);
  for (int y = 0; y < kSide; ++y)
    for (int x = 0; x < kSide; ++x) {
      const size_t p = static_cast<size_t>(y * kSide + x);
      const glm::vec3 t = truth(x, y), a = albedo(x, y);
      for (int c = 0; c < 3; ++c) {
        frame.color[3 * p + static_cast<size_t>(c)] = std::max(0.0f, t[c] + (t[c] > 0.0f ? gaussian(random) : 0.0f));
        frame.parameter(MaterialParameter::BaseColor)[3 * p + static_cast<size_t>(c)] = a[c];
      }
      frame.alpha[p] = 1.0f;
      frame.color_variance[p] = noise * noise;
      frame.normal_world[3 * p + 2] = 1.0f;
      frame.depth[p] = 2.0f;
      frame.label[p] = label(x, y);
    }
  return frame;
}

// RMS over the pixels of the difference between a frame's colour and the truth.
template <class Truth>
double rms_error(const FrameBuffers& frame, Truth truth) {
  double sum = 0.0;
  for (int y = 0; y < frame.height; ++y)
    for (int x = 0; x < frame.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const double d = frame.color[3 * static_cast<size_t>(y * frame.width + x) + static_cast<size_t>(c)] - truth(x, y)[c];
        sum += d * d;
      }
  return std::sqrt(sum / (3.0 * frame.width * frame.height));
}

}  // namespace

TEST_CASE("The denoiser never mixes two materials across their boundary", "[render]") {
  // Red (label 3) on the left, green (label 5) on the right, both noisy: a red pixel next to the
  // green ones takes nothing green (its G stays exactly 0), and each side still loses its noise.
  auto truth = [](int x, int) { return x < kSide / 2 ? glm::vec3(0.6f, 0.0f, 0.0f) : glm::vec3(0.0f, 0.5f, 0.0f); };
  auto albedo = [](int x, int) { return x < kSide / 2 ? glm::vec3(0.8f, 0.0f, 0.0f) : glm::vec3(0.0f, 0.7f, 0.0f); };
  auto label = [](int x, int) { return x < kSide / 2 ? 3 : 5; };
  FrameBuffers frame = noisy_frame(truth, albedo, label, 0.1f, 1);
  const double before = rms_error(frame, truth);
  atrous_filter(frame);
  for (int y = 0; y < kSide; ++y)
    for (int x = 0; x < kSide; ++x) {
      const size_t p = static_cast<size_t>(y * kSide + x);
      INFO("pixel " << x << ", " << y);
      REQUIRE(frame.color[3 * p + (x < kSide / 2 ? 1u : 0u)] == 0.0f);
    }
  const double after = rms_error(frame, truth);
  CAPTURE(before, after);
  CHECK(after < 0.3 * before);
}

TEST_CASE("A checker finer than a pixel keeps its mean, and the texture above it stays sharp", "[render]") {
  // Sub-pixel checker: every pixel's base colour is the checker's mean 0.45 and its colour the
  // lit mean. Above it, a texture of alternating columns (0.2 and 0.8 albedo) under the same
  // light: demodulated by the base colour, the columns stay as they are.
  constexpr float kLight = 0.9f;
  auto albedo = [](int x, int y) { return y < kSide / 2 ? glm::vec3(0.45f) : glm::vec3(x % 2 ? 0.8f : 0.2f); };
  auto truth = [&](int x, int y) { return kLight * albedo(x, y); };
  auto label = [](int, int) { return 7; };
  FrameBuffers frame = noisy_frame(truth, albedo, label, 0.08f, 2);
  const double before = rms_error(frame, truth);
  atrous_filter(frame);
  const double after = rms_error(frame, truth);
  CAPTURE(before, after);
  CHECK(after < 0.35 * before);
}

TEST_CASE("A nearly black object stays finite, non-negative and less noisy", "[render]") {
  auto albedo = [](int, int) { return glm::vec3(0.001f, 0.0f, 0.002f); };
  auto truth = [](int, int) { return glm::vec3(0.0008f, 0.0f, 0.0015f); };
  auto label = [](int, int) { return 2; };
  FrameBuffers frame = noisy_frame(truth, albedo, label, 0.0005f, 3);
  const double before = rms_error(frame, truth);
  atrous_filter(frame);
  for (const float v : frame.color) REQUIRE((std::isfinite(v) && v >= 0.0f));
  const double after = rms_error(frame, truth);
  CAPTURE(before, after);
  CHECK(after < 0.5 * before);
}

TEST_CASE("The denoiser makes no NaN, Inf or negative value from any frame, and leaves bad pixels as they were", "[render]") {
  std::mt19937 random(4);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (int trial = 0; trial < 20; ++trial) {
    FrameBuffers frame;
    frame.resize(17, 11, kAtrousFilterGuideAovs);
    frame.transparent_background = trial % 2 == 0;
    const size_t n = frame.alpha.size();
    for (size_t p = 0; p < n; ++p) {
      for (int c = 0; c < 3; ++c) {
        frame.color[3 * p + static_cast<size_t>(c)] = unit(random) < 0.1f ? 0.0f : 100.0f * unit(random) * unit(random);
        frame.parameter(MaterialParameter::BaseColor)[3 * p + static_cast<size_t>(c)] = unit(random) < 0.2f ? 0.0f : unit(random);
        frame.normal_world[3 * p + static_cast<size_t>(c)] = 2.0f * unit(random) - 1.0f;
      }
      frame.alpha[p] = unit(random) < 0.2f ? 0.0f : unit(random) < 0.5f ? 1.0f : unit(random);
      frame.color_variance[p] = unit(random) < 0.3f ? 0.0f : unit(random);
      frame.depth[p] = unit(random) < 0.1f ? 0.0f : 10.0f * unit(random);
      frame.label[p] = static_cast<int32_t>(random() % 3);
    }
    // Hostile pixels: not finite or negative; the filter leaves them and never reads them.
    frame.color[0] = std::nanf("");
    frame.color[4] = -1.0f;
    frame.color[7] = INFINITY;
    frame.color_variance[5] = std::nanf("");
    const FrameBuffers before = frame;
    atrous_filter(frame);
    CHECK(std::isnan(frame.color[0]));
    CHECK(frame.color[4] == -1.0f);
    CHECK(std::isinf(frame.color[7]));
    for (size_t k = 9; k < frame.color.size(); ++k) {
      INFO("trial " << trial << ", value " << k);
      if (k / 3 == 5) continue;
      REQUIRE(std::isfinite(frame.color[k]));
      REQUIRE(frame.color[k] >= 0.0f);
      if (before.alpha[k / 3] == 0.0f) REQUIRE(frame.color[k] == before.color[k]);  // background untouched
    }
  }
}

TEST_CASE("The denoiser gives the same image on one and two threads", "[render]") {
  auto truth = [](int x, int y) { return glm::vec3(0.3f + 0.01f * x, 0.2f, 0.1f + 0.01f * y); };
  auto albedo = [](int x, int) { return glm::vec3(x % 3 ? 0.5f : 0.3f); };
  auto label = [](int x, int y) { return (x + y) % 17 == 0 ? 2 : 1; };
  FrameBuffers one = noisy_frame(truth, albedo, label, 0.05f, 5), two = one;
  AtrousFilterSettings settings;
  settings.threads = 1;
  atrous_filter(one, settings);
  settings.threads = 2;
  atrous_filter(two, settings);
  CHECK(std::memcmp(one.color.data(), two.color.data(), one.color.size() * sizeof(float)) == 0);
}

TEST_CASE("The denoiser refuses frames without its guides and settings out of range", "[render]") {
  FrameBuffers frame;
  frame.resize(4, 4, AovAlpha | AovDepth);
  CHECK_THROWS_WITH(atrous_filter(frame), Catch::Contains("atrous_filter: the frame has no colour variance"));
  frame.resize(4, 4, kAtrousFilterGuideAovs);
  AtrousFilterSettings settings;
  settings.iterations = 13;
  CHECK_THROWS_WITH(atrous_filter(frame, settings), Catch::Contains("iterations"));
  settings.iterations = 5;
  settings.sigma_luminance = std::nanf("");
  CHECK_THROWS_WITH(atrous_filter(frame, settings), Catch::Contains("sigma"));
  Scene scene;
  scene.add_mesh(test_scenes::horizontal_square(1.0), {scene.add_material(test_scenes::lambert(0.5f))});
  RenderSettings render_settings;
  render_settings.denoise = Denoising::Filter;
  render_settings.cycles_parity = true;
  CHECK_THROWS_WITH(render(scene, Camera::look_at({0, 0, 1}, {0, 0, 0}, {0, 1, 0}, 0.5, 8, 8), render_settings, frame),
                    "render: denoise and cycles_parity exclude each other: Blender 3.4 in Debian has no denoiser");
}

namespace {

// A ball on a floor under a small area lamp, rendered at `spp` (denoised or not) and at 2048
// samples: the colour's RMS error over the covered pixels, and the frames.
struct Comparison {
  double error = 0.0;
  FrameBuffers frame, reference;
};

Comparison render_ball(const Material& ball, int spp, bool denoised) {
  Scene scene;
  test_scenes::add_ball_on_floor(scene, ball, 1.5);
  const Camera camera = test_scenes::ball_on_floor_camera();
  RenderSettings settings;
  settings.aovs = AovAlpha;
  settings.samples_per_pixel = 2048;
  settings.seed = 100;
  Comparison result;
  render(scene, camera, settings, result.reference);
  settings.samples_per_pixel = spp;
  settings.seed = 1;
  settings.denoise = denoised ? Denoising::Filter : Denoising::Off;
  render(scene, camera, settings, result.frame);
  double sum = 0.0;
  for (size_t k = 0; k < result.frame.color.size(); ++k) {
    const double d = result.frame.color[k] - result.reference.color[k];
    sum += d * d;
  }
  result.error = std::sqrt(sum / static_cast<double>(result.frame.color.size()));
  return result;
}

}  // namespace

TEST_CASE("Denoised renders are closer to the converged image than the raw ones", "[render]") {
  // A lamp-lit ball's contact shadow is the filter's hard case (most of what is left is there);
  // textured diffuse surfaces gain about twice as much (README, "Denoising").
  Material grey = test_scenes::lambert(0.5f);
  const Comparison raw = render_ball(grey, 8, false), denoised = render_ball(grey, 8, true);
  CAPTURE(raw.error, denoised.error);
  CHECK(denoised.error < 0.9 * raw.error);
  for (const float v : denoised.frame.color) REQUIRE((std::isfinite(v) && v >= 0.0f));
}

TEST_CASE("A glossy highlight is neither spread nor dimmed", "[render]") {
  Material glossy;
  glossy.set(MaterialParameter::BaseColor, glm::vec3(0.9f, 0.5f, 0.2f));
  glossy.set(MaterialParameter::Metallic, 1.0f);
  glossy.set(MaterialParameter::Roughness, 0.25f);
  const Comparison raw = render_ball(glossy, 16, false), denoised = render_ball(glossy, 16, true);
  // The highlight: the reference's brightest pixel and its luminance.
  auto luminance = [](const FrameBuffers& f, size_t p) {
    return 0.2126f * f.color[3 * p] + 0.7152f * f.color[3 * p + 1] + 0.0722f * f.color[3 * p + 2];
  };
  size_t peak = 0;
  for (size_t p = 0; p < raw.reference.alpha.size(); ++p)
    if (luminance(raw.reference, p) > luminance(raw.reference, peak)) peak = p;
  // The 3 x 3 pixels about it hold as much light as the reference's, within 10 %, and the pixels
  // 4 away in the highlight's row no more than theirs plus 10 % of the peak.
  auto around = [&](const FrameBuffers& f, int dx) {
    const int px = static_cast<int>(peak % 40) + dx, py = static_cast<int>(peak / 40);
    double sum = 0.0;
    for (int y = py - 1; y <= py + 1; ++y)
      for (int x = px - 1; x <= px + 1; ++x) sum += luminance(f, static_cast<size_t>(y * 40 + x));
    return sum;
  };
  CAPTURE(raw.error, denoised.error, around(denoised.frame, 0), around(raw.reference, 0));
  CHECK(around(denoised.frame, 0) == Approx(around(raw.reference, 0)).epsilon(0.1));
  for (const int dx : {-4, 4})
    CHECK(around(denoised.frame, dx) <= around(raw.reference, dx) + 0.1 * around(raw.reference, 0));
  CHECK(denoised.error < raw.error);
}
