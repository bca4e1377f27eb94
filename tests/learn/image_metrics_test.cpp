// The image metrics (libmatlearn/include/matlearn/image_metrics.h) on closed-form cases, against
// scikit-image (Debian's python3-skimage) for SSIM and PSNR, and on bad input.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <string>

#include "matbase/pi.h"
#include "matlearn/image_metrics.h"
#include "noisy_image.h"

using namespace matlearn;

namespace {

// A smooth random image in [0.1, 0.9]: a few sinusoids per channel.
matbase::FloatImage smooth_image(int width, int height, int channels, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> frequency(0.02f, 0.2f), phase(0.0f, 6.28f);
  matbase::FloatImage image(width, height, channels);
  for (int c = 0; c < channels; ++c) {
    const float fx = frequency(rng), fy = frequency(rng), p = phase(rng);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) image.at(x, y, c) = 0.5f + 0.4f * std::sin(fx * x + fy * y + p);
  }
  return image;
}

// A disc covering about half the image.
matbase::Mask disc_mask(int width, int height) {
  matbase::Mask mask(static_cast<size_t>(width) * static_cast<size_t>(height));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float dx = x - 0.5f * width, dy = y - 0.5f * height;
      mask[static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)] =
          dx * dx + dy * dy < 0.16f * width * height;
    }
  return mask;
}

template <class T>
void write_raw(const std::filesystem::path& path, const std::vector<T>& values) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(values.data()), static_cast<std::streamsize>(values.size() * sizeof(T)));
  REQUIRE(out.good());
}

// Runs tests/learn/skimage_metrics.py with Debian's Python on the pair; returns its name -> value lines.
std::map<std::string, double> skimage_metrics(const matbase::FloatImage& truth, const matbase::FloatImage& prediction, double data_range,
                                              const matbase::Mask& mask) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "matpredict_metrics_test";
  std::filesystem::create_directories(dir);
  write_raw(dir / "truth.f32", truth.values);
  write_raw(dir / "prediction.f32", prediction.values);
  write_raw(dir / "mask.u8", mask);
  std::ostringstream command;
  command << MATPREDICT_DEBIAN_PYTHON << " " << MATPREDICT_SKIMAGE_SCRIPT << " " << truth.width << " " << truth.height
          << " " << truth.channels << " " << data_range << " " << dir / "truth.f32" << " " << dir / "prediction.f32"
          << " " << dir / "mask.u8" << " 2>&1";
  FILE* pipe = popen(command.str().c_str(), "r");
  REQUIRE(pipe != nullptr);
  std::string output;
  char buffer[512];
  while (fgets(buffer, sizeof buffer, pipe)) output += buffer;
  const int status = pclose(pipe);
  INFO("command: " << command.str() << "\noutput: " << output
                   << "(needs Debian's python3-skimage: scripts/install_deps.sh installs it)");
  REQUIRE(status == 0);
  std::map<std::string, double> values;
  std::istringstream lines(output);
  std::string name;
  double value;
  while (lines >> name >> value) values[name] = value;
  REQUIRE(values.size() == 3);
  return values;
}

}  // namespace

TEST_CASE("Identical images: RMSE 0, PSNR and SRE infinite, SSIM, UIQ, FSIM, ISSM 1, SAM 0", "[learn]") {
  const matbase::FloatImage image = smooth_image(40, 32, 3, 1);
  CHECK(rmse(image, image, 1.0) == 0.0);
  CHECK(psnr(image, image, 1.0) == std::numeric_limits<double>::infinity());
  CHECK(sre(image, image) == std::numeric_limits<double>::infinity());
  CHECK(ssim(image, image, 1.0) == Approx(1.0).epsilon(1e-12));
  CHECK(uiq(image, image) == Approx(1.0).epsilon(1e-12));
  CHECK(sam_degrees(image, image) == 0.0);
  CHECK(issm(image, image) == 1.0);
  CHECK(fsim(image, image, 1.0) == Approx(1.0).epsilon(1e-12));
}

TEST_CASE("A constant offset gives its closed-form RMSE, PSNR, SRE and ISSM", "[learn]") {
  const matbase::FloatImage truth = smooth_image(40, 32, 3, 2);
  matbase::FloatImage prediction = truth;
  const float offset = 0.0625f;  // exact in binary: the differences carry no rounding
  for (float& v : prediction.values) v += offset;
  CHECK(rmse(truth, prediction, 1.0) == Approx(offset).epsilon(1e-6));
  CHECK(rmse(truth, prediction, 255.0) == Approx(offset / 255.0).epsilon(1e-6));
  CHECK(psnr(truth, prediction, 1.0) == Approx(-20.0 * std::log10(offset)).epsilon(1e-6));
  // SRE: 10 log10(sum X^2 / (N offset^2)); ISSM: 1 / (1 + sqrt(N) offset / ||X||).
  double energy = 0.0;
  for (float v : truth.values) energy += double(v) * v;
  const double n = static_cast<double>(truth.values.size());
  CHECK(sre(truth, prediction) == Approx(10.0 * std::log10(energy / (n * offset * offset))).epsilon(1e-6));
  CHECK(issm(truth, prediction) == Approx(1.0 / (1.0 + std::sqrt(n) * offset / std::sqrt(energy))).epsilon(1e-6));
}

TEST_CASE("SAM of colours rotated by a known angle is that angle", "[learn]") {
  // Colours in the red-green plane rotated about the blue axis by 7 degrees: every pixel's angle
  // is exactly 7 degrees, whatever its length.
  const double angle = 7.0 * matbase::kPi / 180.0;
  matbase::FloatImage truth(16, 16, 3), prediction(16, 16, 3);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> value(0.05f, 1.0f);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      const double r = value(rng), g = value(rng);
      truth.at(x, y, 0) = static_cast<float>(r);
      truth.at(x, y, 1) = static_cast<float>(g);
      prediction.at(x, y, 0) = static_cast<float>(std::cos(angle) * r - std::sin(angle) * g);
      prediction.at(x, y, 1) = static_cast<float>(std::sin(angle) * r + std::cos(angle) * g);
    }
  CHECK(sam_degrees(truth, prediction) == Approx(7.0).epsilon(1e-5));
  // Scaling a colour changes no angle; a tiny angle keeps its precision.
  matbase::FloatImage scaled = truth;
  for (float& v : scaled.values) v *= 3.0f;
  CHECK(sam_degrees(truth, scaled) == Approx(0.0).margin(1e-5));
  matbase::FloatImage nudged = truth;
  nudged.at(5, 5, 2) = 1e-4f * truth.at(5, 5, 0);  // one pixel tilted by about 1e-4 rad
  const double tilt = std::atan2(1e-4 * truth.at(5, 5, 0), std::hypot(truth.at(5, 5, 0), truth.at(5, 5, 1)));
  CHECK(sam_degrees(truth, nudged) == Approx(tilt * 180.0 / matbase::kPi / 256.0).epsilon(1e-3));
}

TEST_CASE("SAM leaves out pixels without a colour", "[learn]") {
  matbase::FloatImage truth(2, 1, 3), prediction(2, 1, 3);
  truth.at(0, 0, 0) = 1.0f;
  prediction.at(0, 0, 1) = 1.0f;  // 90 degrees
  // Pixel 1: black in the truth, no angle.
  prediction.at(1, 0, 2) = 1.0f;
  CHECK(sam_degrees(truth, prediction) == Approx(90.0));
  CHECK(std::isnan(sam_degrees(matbase::FloatImage(2, 1, 3), prediction)));
}

TEST_CASE("UIQ of a periodic pattern against its offset and scaled copies", "[learn]") {
  // A checkerboard of a and b: every 8 x 8 window holds 32 of each, so its mean mu = (a + b) / 2
  // and variance ((a - b) / 2)^2 are the same everywhere, and Q has a closed form.
  const float a = 0.25f, b = 0.625f;  // binary fractions: the shifted and scaled copies are exact
  matbase::FloatImage truth(20, 12, 1);
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 20; ++x) truth.at(x, y, 0) = (x + y) % 2 ? a : b;
  const double mu = 0.5 * (a + b);
  matbase::FloatImage shifted = truth, scaled = truth;
  const float d = 0.25f, s = 0.5f;
  for (float& v : shifted.values) v += d;
  for (float& v : scaled.values) v *= s;
  // y = x + d: cov = var_x = var_y, so Q = 2 mu (mu + d) / (mu^2 + (mu + d)^2).
  CHECK(uiq(truth, shifted) == Approx(2.0 * mu * (mu + d) / (mu * mu + (mu + d) * (mu + d))).epsilon(1e-9));
  // y = s x: Q = 4 s^2 / (1 + s^2)^2.
  CHECK(uiq(truth, scaled) == Approx(4.0 * s * s / ((1.0 + s * s) * (1.0 + s * s))).epsilon(1e-9));
  // Flat images: Q = 2 mu_x mu_y / (mu_x^2 + mu_y^2), and 1 for two black images.
  const matbase::FloatImage flat_a(10, 10, 1, 0.3f), flat_b(10, 10, 1, 0.6f);
  CHECK(uiq(flat_a, flat_b) == Approx(2.0 * 0.3 * 0.6 / (0.09 + 0.36)).epsilon(1e-6));
  CHECK(uiq(matbase::FloatImage(10, 10, 1), matbase::FloatImage(10, 10, 1)) == 1.0);
}

TEST_CASE("SSIM and PSNR equal scikit-image's, with and without a mask", "[learn]") {
  for (const int channels : {1, 3}) {
    const matbase::FloatImage truth = smooth_image(48, 40, channels, 10 + channels);
    const matbase::FloatImage prediction = plus_noise(truth, 0.03f, 20 + channels);
    const matbase::Mask mask = disc_mask(48, 40);
    for (const double data_range : {1.0, 2.0}) {
      INFO(channels << " channels, data range " << data_range);
      const std::map<std::string, double> reference = skimage_metrics(truth, prediction, data_range, mask);
      CHECK(ssim(truth, prediction, data_range) == Approx(reference.at("ssim")).margin(1e-9));
      CHECK(psnr(truth, prediction, data_range) == Approx(reference.at("psnr")).epsilon(1e-9));
      CHECK(ssim(truth, prediction, data_range, mask) == Approx(reference.at("ssim_masked")).margin(1e-9));
    }
  }
}

TEST_CASE("Masked metrics see only the covered pixels", "[learn]") {
  const matbase::FloatImage truth = smooth_image(32, 32, 3, 4);
  const matbase::Mask mask = disc_mask(32, 32);
  // Ruin every pixel outside the mask: the masked metrics cannot tell.
  matbase::FloatImage prediction = truth;
  for (size_t p = 0; p < truth.pixel_count(); ++p)
    if (!mask[p])
      for (int c = 0; c < 3; ++c) prediction.values[p * 3 + static_cast<size_t>(c)] = 1.0f - prediction.values[p * 3 + static_cast<size_t>(c)];
  CHECK(rmse(truth, prediction, 1.0, mask) == 0.0);
  CHECK(psnr(truth, prediction, 1.0, mask) == std::numeric_limits<double>::infinity());
  CHECK(sam_degrees(truth, prediction, mask) == 0.0);
  CHECK(rmse(truth, prediction, 1.0) > 0.05);
  CHECK(sam_degrees(truth, prediction) > 1.0);
}

TEST_CASE("Mismatched or empty inputs are clear errors", "[learn]") {
  const matbase::FloatImage a = smooth_image(16, 16, 3, 5), b = smooth_image(16, 12, 3, 6), gray = smooth_image(16, 16, 1, 7);
  CHECK_THROWS_WITH(rmse(a, b, 1.0), Catch::Contains("16x12x3") && Catch::Contains("16x16x3"));
  CHECK_THROWS_WITH(ssim(a, gray, 1.0), Catch::Contains("SSIM"));
  CHECK_THROWS_WITH(psnr(a, a, 0.0), Catch::Contains("data range"));
  CHECK_THROWS_WITH(sam_degrees(a, a, matbase::Mask(10, 1)), Catch::Contains("10 entries for 256 pixels"));
  CHECK_THROWS_WITH(uiq(a, a, matbase::Mask(256, 0)), Catch::Contains("covers no pixel"));
  CHECK_THROWS_WITH(ssim(matbase::FloatImage(5, 5, 1), matbase::FloatImage(5, 5, 1), 1.0), Catch::Contains("smaller than its 7x7 window"));
  CHECK_THROWS_WITH(sre(matbase::FloatImage(), matbase::FloatImage()), Catch::Contains("empty"));
}
