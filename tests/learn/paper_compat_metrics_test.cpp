// The paper-compatible metrics (matlearn/paper_compat_metrics.h): the conventions of
// image-similarity-measures on 8-bit images, by closed forms, and the signature of the paper's
// table (SAM near 90 degrees, RMSE 16 times too small) beside the correct metrics.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "matbase/pi.h"
#include "matlearn/image_metrics.h"
#include "matlearn/paper_compat_metrics.h"

using namespace matlearn;
namespace compat = matlearn::paper_compat;

namespace {

compat::Image8 image8(int width, int height, int channels, std::vector<uint8_t> values) {
  return compat::Image8{width, height, channels, std::move(values)};
}

// A smooth 8-bit RGB image and the same plus Gaussian noise of `sigma` grey levels, as floats in
// [0, 1] (the correct metrics) and quantised (the compatible ones).
struct NoisyPair {
  matbase::FloatImage truth, prediction;
};

NoisyPair smooth_and_noisy(int size, float sigma_grey_levels) {
  std::mt19937 rng(42);
  std::normal_distribution<float> noise(0.0f, sigma_grey_levels);
  NoisyPair pair{matbase::FloatImage(size, size, 3), matbase::FloatImage(size, size, 3)};
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      for (int c = 0; c < 3; ++c) {
        const float grey = std::round(128.0f + 80.0f * std::sin(0.05f * x + 0.03f * y + 2.0f * c));
        pair.truth.at(x, y, c) = grey / 255.0f;
        pair.prediction.at(x, y, c) = std::clamp(std::round(grey + noise(rng)), 0.0f, 255.0f) / 255.0f;
      }
  return pair;
}

}  // namespace

TEST_CASE("Quantising to 8 bits rounds and clamps", "[learn]") {
  matbase::FloatImage image(6, 1, 1);
  image.values = {0.0f, 1.0f, 0.5f, -0.2f, 1.7f, std::nanf("")};
  CHECK(compat::quantize_8bit(image).values == std::vector<uint8_t>{0, 255, 128, 0, 255, 0});
}

TEST_CASE("Paper-compatible SAM multiplies in 8 bits", "[learn]") {
  // (16,16,16) . (16,16,16): each product 256 wraps to 0, so the angle is 90 degrees.
  CHECK(compat::sam_degrees(image8(1, 1, 3, {16, 16, 16}), image8(1, 1, 3, {16, 16, 16})) == Approx(90.0));
  // 10 * 20 = 200 fits: the true angle, 0.
  CHECK(compat::sam_degrees(image8(1, 1, 3, {10, 0, 0}), image8(1, 1, 3, {20, 0, 0})) == Approx(0.0).margin(1e-6));
  // 100 * 3 = 300 wraps to 44: acos(44 / 300).
  CHECK(compat::sam_degrees(image8(1, 1, 3, {100, 0, 0}), image8(1, 1, 3, {3, 0, 0})) ==
        Approx(std::acos(44.0 / 300.0) * 180.0 / matbase::kPi));
  // One black pixel makes the package's mean NaN, reported as 0.
  CHECK(compat::sam_degrees(image8(2, 1, 3, {0, 0, 0, 100, 0, 0}), image8(2, 1, 3, {5, 5, 5, 3, 0, 0})) == 0.0);
}

TEST_CASE("Paper-compatible RMSE, PSNR and SRE use max_p 4095 and the unsquared norm", "[learn]") {
  // Truth 100 and 50 in two bands, prediction 4 grey levels higher everywhere (16 pixels).
  std::vector<uint8_t> truth_values, prediction_values;
  for (int p = 0; p < 16; ++p) {
    truth_values.insert(truth_values.end(), {100, 50});
    prediction_values.insert(prediction_values.end(), {104, 54});
  }
  const compat::Image8 truth = image8(4, 4, 2, truth_values), prediction = image8(4, 4, 2, prediction_values);
  CHECK(compat::rmse(truth, prediction) == Approx(4.0 / 4095.0));
  CHECK(compat::psnr(truth, prediction) == Approx(20.0 * std::log10(4095.0 / 4.0)));
  // ||x - y|| = 4 sqrt(16) = 16 per band, divided by 16 pixels: 1; ratios 100^2 and 50^2.
  CHECK(compat::sre(truth, prediction) == Approx(10.0 * std::log10((100.0 * 100.0 + 50.0 * 50.0) / 2.0)));
}

TEST_CASE("Paper-compatible ISSM is 0 on 8-bit images, the correct one in (0, 1]", "[learn]") {
  const NoisyPair pair = smooth_and_noisy(64, 3.0f);
  CHECK(compat::issm(compat::quantize_8bit(pair.truth), compat::quantize_8bit(pair.prediction)) == 0.0);
  const double correct = issm(pair.truth, pair.prediction);
  CHECK(correct > 0.9);
  CHECK(correct < 1.0);
}

TEST_CASE("Paper-compatible UIQ scores equal flat windows 0", "[learn]") {
  const compat::Image8 flat = image8(8, 8, 1, std::vector<uint8_t>(64, 90));
  matbase::FloatImage flat_float(8, 8, 1, 90.0f);
  CHECK(compat::uiq(flat, flat) == 0.0);
  CHECK(uiq(flat_float, flat_float) == 1.0);
}

TEST_CASE("The paper's signature: 8-bit near-identical images give SAM near 90 degrees", "[learn]") {
  // docs/metrics.md: the package on a smooth 224 x 224 8-bit image against itself
  // plus noise of 3 grey levels gives RMSE 0.00074, SSIM 0.9994, SAM 89.2 degrees; the correct
  // metrics on the same pair as floats give RMSE 0.0119, SSIM 0.873 and SAM 1.26 degrees (their
  // image; ours is another smooth image, so the values agree to within the image's influence).
  const NoisyPair pair = smooth_and_noisy(224, 3.0f);
  const compat::Image8 truth8 = compat::quantize_8bit(pair.truth), prediction8 = compat::quantize_8bit(pair.prediction);
  const double compat_rmse = compat::rmse(truth8, prediction8), compat_sam = compat::sam_degrees(truth8, prediction8);
  const double compat_ssim = compat::ssim(truth8, prediction8);
  const double true_rmse = rmse(pair.truth, pair.prediction, 1.0), true_sam = sam_degrees(pair.truth, pair.prediction);
  INFO("compat RMSE " << compat_rmse << " SSIM " << compat_ssim << " SAM " << compat_sam << "; correct RMSE "
                      << true_rmse << " SAM " << true_sam);
  // The RMSE of 3 grey levels, divided by 4095 instead of 255 (and averaged over bands instead
  // of pooled, which the equal noise in every band makes nearly the same).
  CHECK(compat_rmse == Approx(true_rmse * 255.0 / 4095.0).epsilon(1e-4));
  CHECK(true_rmse == Approx(3.0 / 255.0).epsilon(0.05));
  CHECK(compat_ssim > 0.999);
  CHECK(compat_sam > 85.0);
  CHECK(compat_sam < 90.0);
  CHECK(true_sam < 3.0);
}
