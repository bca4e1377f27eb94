// Phase congruency (libmatlearn/src/metrics/phase_congruency) on images of known structure, and
// FSIM built on it (matlearn/image_metrics.h, matlearn/paper_compat_metrics.h).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "matlearn/image_metrics.h"
#include "matlearn/paper_compat_metrics.h"
#include "metrics/phase_congruency.h"
#include "noisy_image.h"

using namespace matlearn;

namespace {

constexpr int kSize = 64;

double at(const std::vector<double>& v, int x, int y) { return v[static_cast<size_t>(y * kSize + x)]; }

// Columns x < 32 dark, x > 32 bright and column 32 halfway, so the step is centred on that
// column (the transform is periodic: a second step at the image's left and right borders).
std::vector<double> step_image(double dark, double bright) {
  std::vector<double> v(kSize * kSize);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      v[static_cast<size_t>(y * kSize + x)] = x < 32 ? dark : (x > 32 ? bright : 0.5 * (dark + bright));
  return v;
}

matbase::FloatImage textured_image(uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> frequency(0.05f, 0.4f), phase(0.0f, 6.28f);
  matbase::FloatImage image(kSize, kSize, 3);
  for (int c = 0; c < 3; ++c) {
    const float f1 = frequency(rng), f2 = frequency(rng), p = phase(rng);
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x)
        image.at(x, y, c) = 0.5f + 0.25f * std::sin(f1 * x + p) + 0.15f * std::cos(f2 * y + 0.5f * x) +
                            (x > 20 && x < 40 && y > 25 ? 0.1f : 0.0f);  // and an edged block
  }
  return image;
}

}  // namespace

TEST_CASE("Phase congruency is high on a step edge and low on flat ground", "[learn]") {
  const PhaseCongruency pc = phase_congruency(step_image(0.2, 0.8), kSize, kSize, PhaseCongruencySettings{});
  for (int y : {10, 32, 50}) {
    INFO("row " << y << ": at the step " << at(pc.overall, 32, y) << ", beside it " << at(pc.overall, 31, y)
                << ", flat " << at(pc.overall, 16, y) << ", " << at(pc.overall, 48, y));
    // Near 1 on the step (the sigmoid spread weight, the noise threshold and the periodic second
    // step keep it a little lower), about half one pixel off, nothing on flat ground.
    CHECK(at(pc.overall, 32, y) > 0.85);
    CHECK(at(pc.overall, 32, y) <= 1.0);
    CHECK(at(pc.overall, 31, y) < 0.6);
    CHECK(at(pc.overall, 16, y) < 0.05);
    CHECK(at(pc.overall, 48, y) < 0.05);
  }
  // A vertical edge excites the orientation across it (0: filters tuned to horizontal
  // frequencies) far more than the one along it (3 of 6: vertical frequencies).
  CHECK(at(pc.per_orientation[0], 32, 32) > 10.0 * at(pc.per_orientation[3], 32, 32));
}

TEST_CASE("Phase congruency marks a thin line as well as an edge", "[learn]") {
  std::vector<double> line(kSize * kSize, 0.3);
  for (int x = 0; x < kSize; ++x) line[static_cast<size_t>(40 * kSize + x)] = 0.9;  // row 40
  const PhaseCongruency pc = phase_congruency(line, kSize, kSize, PhaseCongruencySettings{});
  CHECK(at(pc.overall, 20, 40) > 0.5);
  CHECK(at(pc.overall, 20, 10) < 0.05);
}

TEST_CASE("Phase congruency ignores brightness and contrast", "[learn]") {
  const matbase::FloatImage image = textured_image(1);
  std::vector<double> v(kSize * kSize), scaled(kSize * kSize);
  for (size_t p = 0; p < v.size(); ++p) {
    v[p] = image.values[3 * p];
    scaled[p] = 3.0 * v[p] + 0.1;
  }
  const PhaseCongruency a = phase_congruency(v, kSize, kSize, PhaseCongruencySettings{});
  const PhaseCongruency b = phase_congruency(scaled, kSize, kSize, PhaseCongruencySettings{});
  double worst = 0.0;
  for (size_t p = 0; p < v.size(); ++p) worst = std::max(worst, std::abs(a.overall[p] - b.overall[p]));
  CHECK(worst < 2e-3);  // only the 1e-4 guards against division by zero do not scale
  CHECK(*std::max_element(a.overall.begin(), a.overall.end()) > 0.3);  // there is structure to compare
}

TEST_CASE("FSIM is 1 for identical images and falls as noise grows", "[learn]") {
  const matbase::FloatImage image = textured_image(2);
  CHECK(fsim(image, image, 1.0) == Approx(1.0).epsilon(1e-12));
  double previous = 1.0;
  for (float sigma : {0.01f, 0.03f, 0.1f}) {
    const double value = fsim(image, plus_noise(image, sigma, 7), 1.0);
    INFO("noise " << sigma << ": FSIM " << value);
    CHECK(value < previous);
    CHECK(value > 0.0);
    previous = value;
  }
  CHECK(std::isnan(fsim(matbase::FloatImage(kSize, kSize, 1, 0.5f), matbase::FloatImage(kSize, kSize, 1, 0.5f), 1.0)));
}

TEST_CASE("FSIM does not depend on the units of the data range", "[learn]") {
  // Gradients scale with the values and T2 with the square of the range; phase congruency
  // does not scale at all.
  const matbase::FloatImage truth = textured_image(3), prediction = plus_noise(truth, 0.03f, 8);
  matbase::FloatImage truth_255 = truth, prediction_255 = prediction;
  for (float& v : truth_255.values) v *= 255.0f;
  for (float& v : prediction_255.values) v *= 255.0f;
  CHECK(fsim(truth_255, prediction_255, 255.0) == Approx(fsim(truth, prediction, 1.0)).margin(2e-3));
}

TEST_CASE("Paper-compatible FSIM is 1 for identical images and below 1 otherwise", "[learn]") {
  const matbase::FloatImage truth = textured_image(4), prediction = plus_noise(truth, 0.03f, 9);
  const paper_compat::Image8 truth8 = paper_compat::quantize_8bit(truth);
  const paper_compat::Image8 prediction8 = paper_compat::quantize_8bit(prediction);
  CHECK(paper_compat::fsim(truth8, truth8) == Approx(1.0).epsilon(1e-12));
  const double noisy = paper_compat::fsim(truth8, prediction8);
  CHECK(noisy < 1.0);
  CHECK(noisy > 0.0);
}
