// Rendering to an error (RenderSettings::target_error): the prediction from a pixel's two halves
// on sums built by hand, undenoised and through a denoiser that changes nothing, the rounds' plan,
// and a lamp-lit ball rendered to a target, undenoised and with the a-trous filter, against two
// independent high-sample references (their own noise taken out of the measured error).
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "film/denoised_error.h"
#include "film/error_target.h"
#include "matrender/camera.h"
#include "matrender/lamp.h"
#include "matrender/render.h"
#include "matrender/render_setting_declarations.h"
#include "matrender/scene.h"
#include "test_scenes.h"

using namespace matrender;

namespace {

// A covered pixel of n samples whose two halves have the means `first` and `second` (grey).
PixelSums pixel(uint32_t n, double first, double second) {
  PixelSums s;
  s.samples = n;
  s.coverage = n;
  s.first_half = glm::dvec3(first * n / 2.0);
  s.color = s.first_half + glm::dvec3(second * n / 2.0);
  return s;
}

// A ball on a floor under a small area lamp (30 cm), 40 x 32.
struct BallScene {
  Scene scene;
  Camera camera = test_scenes::ball_on_floor_camera();

  explicit BallScene(const Material& ball) { test_scenes::add_ball_on_floor(scene, ball, 0.3); }

  FrameBuffers render_with(RenderSettings settings, RenderStats* stats = nullptr) {
    settings.aovs = AovAlpha;
    FrameBuffers frame;
    const RenderStats s = render(scene, camera, settings, frame);
    if (stats) *stats = s;
    return frame;
  }
};

double mean_squared_difference(const FrameBuffers& a, const FrameBuffers& b) {
  double sum = 0.0;
  for (size_t k = 0; k < a.color.size(); ++k) sum += (a.color[k] - b.color[k]) * (a.color[k] - b.color[k]);
  return sum / static_cast<double>(a.color.size());
}

double mean_colour(const FrameBuffers& frame) {
  double sum = 0.0;
  for (const float v : frame.color) sum += v;
  return sum / static_cast<double>(frame.color.size());
}

// Two independent 8192-sample renders of a scene: the first is the reference, and half their
// squared difference is its own squared error, which the measured error leaves out.
struct References {
  FrameBuffers first;
  double own_mse = 0.0;
  double mean = 0.0;

  References(BallScene& scene, RenderSettings settings) {
    settings.samples_per_pixel = 8192;
    settings.seed = 11;
    first = scene.render_with(settings);
    settings.seed = 12;
    own_mse = 0.5 * mean_squared_difference(first, scene.render_with(settings));
    mean = mean_colour(first);
  }

  // A frame's relative RMSE against the converged image.
  double error_of(const FrameBuffers& frame) const {
    return std::sqrt(std::max(0.0, mean_squared_difference(frame, first) - own_mse)) / mean;
  }
};

}  // namespace

TEST_CASE("A frame's error is predicted from its pixels' halves: (A - B)^2 / 4 over the covered pixels", "[render]") {
  // Two covered pixels of mean 1: halves 0.9 / 1.1 and 1.2 / 0.8, squared errors 0.01 and 0.04
  // per channel; their mean 0.025, over a mean colour of 1.
  std::vector<PixelSums> sums = {pixel(16, 0.9, 1.1), pixel(64, 1.2, 0.8), PixelSums()};
  sums[2].samples = 16;  // no coverage: not counted
  const FrameErrorEstimate estimate = predict_frame_error(sums);
  CHECK(estimate.pixels == 2);
  CHECK(estimate.mean == Approx(1.0));
  CHECK(estimate.mean_squared_error == Approx(0.025));
  CHECK(estimate.relative_rmse == Approx(std::sqrt(0.025)));
  // A black frame, or none covered: 0, never a division by 0.
  CHECK(predict_frame_error({pixel(16, 0.0, 0.0)}).relative_rmse == 0.0);
  CHECK(predict_frame_error({PixelSums()}).pixels == 0);
}

TEST_CASE("A round doubles the pixels that take most error off per sample, just enough to reach the target",
          "[render]") {
  // A 7 x 1 frame, its pixels farther apart than the spread's 5 x 5 neighbourhood: a quiet pixel,
  // nothing, and a noisy one. Predicted: the noisy pixel's 0.16 a channel over two pixels, 0.08.
  std::vector<PixelSums> sums(7);
  sums[0] = pixel(16, 1.0, 1.0);
  sums[6] = pixel(16, 0.6, 1.4);
  std::vector<uint32_t> counts(7, 16);
  const double predicted = predict_frame_error(sums).relative_rmse;
  REQUIRE(predicted == Approx(std::sqrt(0.08)));
  // 10 % above the target: doubling the noisy pixel takes off 0.08 of the sum 0.16, more than the
  // 0.03 needed, and the quiet one is not doubled.
  REQUIRE(plan_error_target_round(sums, 7, 1, predicted / 1.1, 1024, counts));
  CHECK(counts == std::vector<uint32_t>{16, 16, 16, 16, 16, 16, 32});
  // At or below it: nothing more.
  counts.assign(7, 16);
  CHECK_FALSE(plan_error_target_round(sums, 7, 1, predicted, 1024, counts));
  CHECK(counts == std::vector<uint32_t>(7, 16));
  // Every pixel at the cap: nothing more, whatever the error.
  CHECK_FALSE(plan_error_target_round(sums, 7, 1, 1e-6, 16, counts));
  CHECK(power_of_two_at_most(1000) == 512);
  CHECK(power_of_two_at_most(1024) == 1024);
  CHECK(power_of_two_at_most(1) == 1);
}

TEST_CASE("A pixel beside covered ones that met no surface doubles while it has under half their samples",
          "[render]") {
  // A 4 x 1 frame: a noisy covered pixel of 64 samples, its uncovered neighbours of 16 and of 32,
  // and an uncovered pixel beside no covered one. The noisy pixel doubles to 128: the neighbour of
  // 16 doubles (32 < 128 / 2 = 64 would still hold after), the one of 32 too (32 < 64); the far
  // one stays.
  std::vector<PixelSums> sums = {PixelSums(), pixel(64, 0.6, 1.4), PixelSums(), PixelSums()};
  sums[0].samples = 16;
  sums[2].samples = 32;
  sums[3].samples = 16;
  std::vector<uint32_t> counts = {16, 64, 32, 16};
  REQUIRE(plan_error_target_round(sums, 4, 1, 0.01, 1024, counts));
  CHECK(counts == std::vector<uint32_t>{32, 128, 64, 16});
  // They ride along with the covered pixels' rounds: with the covered pixel at the cap there is
  // no round.
  counts = {16, 64, 32, 16};
  CHECK_FALSE(plan_error_target_round(sums, 4, 1, 0.01, 64, counts));
  CHECK(counts == std::vector<uint32_t>{16, 64, 32, 16});
}

TEST_CASE("A lamp-lit ball rendered to a target error has that error against independent references", "[render]") {
  for (const float roughness : {1.0f, 0.3f}) {
    Material ball = test_scenes::lambert(0.5f);
    if (roughness < 1.0f) {
      ball.diffuse_model = DiffuseModel::Principled;
      ball.set(MaterialParameter::Specular, 0.5f);
      ball.set(MaterialParameter::Roughness, roughness);
    }
    BallScene ball_scene(ball);
    RenderSettings settings;
    const References references(ball_scene, settings);
    // The first round's 16 samples give the ball about 5 % (matte) and 7 % (glossy): a target
    // below that is met by sampling on.
    for (const double target : {0.03, 0.015}) {
      settings.samples_per_pixel = 4096;
      settings.target_error = target;
      settings.seed = 13;
      RenderStats stats;
      const FrameBuffers frame = ball_scene.render_with(settings, &stats);
      const double measured = references.error_of(frame);
      CAPTURE(roughness, target, measured, stats.predicted_error, std::sqrt(references.own_mse) / references.mean,
              stats.camera_samples / 1280.0);
      CHECK(stats.predicted_error <= target);
      CHECK(measured == Approx(target).epsilon(0.25));
    }
  }
}

TEST_CASE("Rendering to an error gives the same image on 1 and 2 threads, and excludes the noise threshold", "[render]") {
  BallScene ball_scene(test_scenes::lambert(0.5f));
  RenderSettings settings;
  settings.samples_per_pixel = 256;
  settings.target_error = 0.05;
  settings.threads = 1;
  const FrameBuffers one = ball_scene.render_with(settings);
  settings.threads = 2;
  CHECK(ball_scene.render_with(settings).color == one.color);
  settings.noise_threshold = 0.01;
  CHECK(render_settings_problem(settings) ==
        std::string("target_error and noise_threshold exclude each other: both decide where sampling stops; give one"));
  settings.noise_threshold = 0.0;
  settings.cycles_parity = true;
  CHECK(render_settings_problem(settings)->find("target_error and cycles_parity exclude each other") == 0);
}

TEST_CASE("The denoised error of a denoiser that changes nothing is the halves' error at n^(-1/3)", "[render]") {
  // Four covered pixels whose halves differ by 0.2 and 0.4: each half's squared error
  // (A - B)^2 / 2, the halves' own noise, is all that remains of the cross terms; a doubling then
  // takes 2^(-2/3) off it. The undenoised prediction, (A - B)^2 / 4, is 2^(-1/3) below that.
  struct Nothing : Denoiser {
    uint32_t guide_aovs() const override { return AovAlpha; }
    void denoise(FrameBuffers&, int) const override {}
  };
  const std::vector<PixelSums> sums = {pixel(16, 0.9, 1.1), pixel(32, 1.2, 0.8), pixel(16, 1.1, 0.9),
                                       pixel(64, 0.8, 1.2)};
  FrameBuffers accumulating;
  accumulating.resize(2, 2, AovAlpha);
  const FrameErrorEstimate raw = predict_frame_error(sums);
  const FrameErrorEstimate denoised = predict_denoised_error(sums, raw, accumulating, Nothing(), glm::mat3(1.0f), 1);
  CHECK(denoised.pixels == 4);
  CHECK(denoised.mean == Approx(1.0));
  CHECK(raw.mean_squared_error == Approx((0.01 + 0.04 + 0.01 + 0.04) / 4.0));
  CHECK(denoised.mean_squared_error == Approx(2.0 * raw.mean_squared_error * std::pow(2.0, -2.0 / 3.0)));
  CHECK(denoised.relative_rmse == Approx(std::sqrt(denoised.mean_squared_error)));
}

TEST_CASE("With a denoiser, a target error holds for the denoised frame against independent references",
          "[render]") {
  BallScene ball_scene(test_scenes::lambert(0.5f));
  RenderSettings settings;
  const References references(ball_scene, settings);
  settings.denoise = Denoising::Filter;
  settings.samples_per_pixel = 4096;
  settings.seed = 13;
  for (const double target : {0.03, 0.015}) {
    settings.target_error = target;
    RenderStats stats;
    settings.threads = 2;
    const FrameBuffers frame = ball_scene.render_with(settings, &stats);
    const double measured = references.error_of(frame);
    CAPTURE(target, measured, stats.predicted_error, stats.camera_samples / 1280.0);
    CHECK(stats.predicted_error <= target);
    CHECK(measured == Approx(target).epsilon(0.25));
    // The halves are denoised on the render's threads: the same image on one.
    settings.threads = 1;
    CHECK(ball_scene.render_with(settings).color == frame.color);
  }
}

