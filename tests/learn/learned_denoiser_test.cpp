// The learned denoiser: its U-Net against Open Image Denoise's design written independently in
// PyTorch (tests/learn/oidn_unet_reference.py), the HDR transfer function and auto-exposure
// against their closed forms, hostile frames, determinism across thread counts, and render()
// running it.
#define CATCH_CONFIG_PREFIX_ALL
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <vector>

#include "matlearn/denoising/denoiser_input.h"
#include "matlearn/denoising/denoising_unet.h"
#include "matlearn/denoising/hdr_transfer.h"
#include "matlearn/denoising/learned_denoiser.h"
#include "matlearn/models/state_dict.h"
#include "matrender/camera.h"
#include "matrender/denoiser.h"
#include "matrender/render.h"
#include "test_scenes.h"

namespace fs = std::filesystem;
using namespace matlearn;

namespace {

// A network of seeded random weights, the same in every run.
DenoisingUNet seeded_network(uint64_t seed) {
  torch::manual_seed(seed);
  return DenoisingUNet();
}

// A frame of random colour (with a bright highlight), albedo and normal, and a transparent
// border.
struct RandomFrame {
  int width, height;
  std::vector<float> color, albedo, normal, coverage;

  RandomFrame(int w, int h, uint32_t seed) : width(w), height(h) {
    const size_t n = static_cast<size_t>(w) * static_cast<size_t>(h);
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    color.resize(3 * n), albedo.resize(3 * n), normal.resize(3 * n), coverage.resize(n);
    for (size_t p = 0; p < n; ++p) {
      const int x = static_cast<int>(p % static_cast<size_t>(w)), y = static_cast<int>(p / static_cast<size_t>(w));
      coverage[p] = (x == 0 || y == 0) ? 0.0f : 1.0f;
      for (size_t c = 0; c < 3; ++c) {
        color[3 * p + c] = coverage[p] * unit(random) * (p == n / 2 ? 500.0f : 1.0f);
        albedo[3 * p + c] = unit(random);
        normal[3 * p + c] = 2.0f * unit(random) - 1.0f;
      }
    }
  }
  DenoiserFrame view() const { return {width, height, color.data(), albedo.data(), normal.data(), coverage.data()}; }
};

// The transfer function and its inverse on one value.
float transfer(float v) { return hdr_transfer(torch::tensor({v})).item<float>(); }
float transfer_inverse(float t) { return hdr_transfer_inverse(torch::tensor({t})).item<float>(); }

bool finite_non_negative(const std::vector<float>& values) {
  for (const float v : values)
    if (!(std::isfinite(v) && v >= 0.0f)) return false;
  return true;
}

}  // namespace

CATCH_TEST_CASE("The denoising U-Net is Open Image Denoise's, as PyTorch builds it from the design", "[learn]") {
  const fs::path dir = fs::temp_directory_path() / "matpredict_oidn_unet_reference";
  fs::create_directories(dir);
  const std::string command = std::string(MATPREDICT_DEBIAN_PYTHON) + " " + MATPREDICT_OIDN_UNET_SCRIPT + " " +
                              dir.string() + " > " + (dir / "count.txt").string();
  CATCH_REQUIRE(std::system(command.c_str()) == 0);
  DenoisingUNet network;
  // Strict: every name and shape of the reference's state dict, and no other.
  load_state_dict(*network, dir / "weights.pth");
  int64_t parameters = 0;
  for (const torch::Tensor& p : network->parameters()) parameters += p.numel();
  int64_t reference_parameters = 0;
  std::ifstream(dir / "count.txt") >> reference_parameters;
  CATCH_CHECK(parameters == reference_parameters);
  network->eval();
  const std::map<std::string, torch::Tensor> io = read_state_dict(dir / "io.pt");
  const torch::NoGradGuard no_grad;
  const torch::Tensor ours = network->forward(io.at("input"));
  CATCH_CHECK(ours.sizes() == io.at("output").sizes());
  CATCH_CHECK(torch::allclose(ours, io.at("output"), 1e-5, 1e-6));
}

CATCH_TEST_CASE("The HDR transfer function is equation 1 and its inverse undoes it", "[learn]") {
  const double scale = std::log1p(65504.0 * 256.0);
  for (const double v : {0.0, 1e-4, 1.0 / 256.0, 0.18, 1.0, 37.0, 65504.0}) {
    CATCH_CAPTURE(v);
    CATCH_CHECK(transfer(static_cast<float>(v)) == Approx(std::log1p(256.0 * v) / scale).margin(1e-6));
    CATCH_CHECK(transfer_inverse(transfer(static_cast<float>(v))) == Approx(v).epsilon(1e-4).margin(1e-6));
  }
  CATCH_CHECK(transfer(0.0f) == 0.0f);
  CATCH_CHECK(transfer(65504.0f) == Approx(1.0f));
  // Out of range and non-finite values go to the nearest end, never NaN.
  CATCH_CHECK(transfer(-3.0f) == 0.0f);
  CATCH_CHECK(transfer(std::numeric_limits<float>::infinity()) == Approx(1.0f));
  CATCH_CHECK(transfer(std::numeric_limits<float>::quiet_NaN()) == 0.0f);
  CATCH_CHECK(transfer_inverse(2.0f) == Approx(65504.0f));
  CATCH_CHECK(transfer_inverse(-1.0f) == 0.0f);
}

CATCH_TEST_CASE("Auto-exposure puts the log-average luminance of the lit blocks at 0.18", "[learn]") {
  // Two halves of luminance 0.5 and 2 (grey): log-average 1, whatever the empty border.
  const int w = 64, h = 32;
  std::vector<float> rgb(3 * static_cast<size_t>(w * h), 0.0f);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < 32; ++x)
      for (int c = 0; c < 3; ++c) rgb[3 * static_cast<size_t>(y * w + x) + static_cast<size_t>(c)] = x < 16 ? 0.5f : 2.0f;
  CATCH_CHECK(auto_exposure(rgb.data(), w, h) == Approx(0.18f).epsilon(1e-5));
  // Black, NaN and negative everywhere: no exposure is measured, 1.
  std::vector<float> dark(3 * static_cast<size_t>(w * h), -1.0f);
  dark[0] = std::numeric_limits<float>::quiet_NaN();
  CATCH_CHECK(auto_exposure(dark.data(), w, h) == 1.0f);
}

CATCH_TEST_CASE("The learned denoiser gives the same image on 1 and 2 threads, of the frame's size", "[learn]") {
  const LearnedDenoiser denoiser(seeded_network(3));
  const RandomFrame frame(37, 21, 5);  // neither side a multiple of 16
  const std::vector<float> one = denoiser.denoised_colour(frame.view(), 1);
  const std::vector<float> two = denoiser.denoised_colour(frame.view(), 2);
  CATCH_REQUIRE(one.size() == frame.color.size());
  CATCH_CHECK(one == two);
  CATCH_CHECK(finite_non_negative(one));
}

CATCH_TEST_CASE("The learned denoiser makes no NaN, Inf or negative value from any frame", "[learn]") {
  const LearnedDenoiser denoiser(seeded_network(4));
  RandomFrame frame(20, 20, 6);
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  const std::vector<float> hostile = {nan, inf, -inf, -5.0f, 1e30f, 0.0f, 3.4e38f};
  for (size_t i = 0; i < frame.color.size(); i += 7) {
    frame.color[i] = hostile[i % hostile.size()];
    frame.albedo[i] = hostile[(i + 1) % hostile.size()];
    frame.normal[i] = hostile[(i + 2) % hostile.size()];
  }
  frame.coverage[5] = nan;
  CATCH_CHECK(finite_non_negative(denoiser.denoised_colour(frame.view(), 2)));
  // All black, and one pixel.
  RandomFrame black(16, 16, 7);
  std::fill(black.color.begin(), black.color.end(), 0.0f);
  CATCH_CHECK(finite_non_negative(denoiser.denoised_colour(black.view(), 2)));
  const RandomFrame pixel(1, 1, 8);
  CATCH_CHECK(denoiser.denoised_colour(pixel.view(), 2).size() == 3);
}

CATCH_TEST_CASE("render() runs the learned denoiser a program provides, and refuses it when none is", "[learn]") {
  matrender::Scene scene;
  const uint32_t grey = scene.add_material(test_scenes::lambert(0.5f));
  scene.add_mesh(test_scenes::uv_sphere(0.5, 12), {grey});
  scene.set_background(matrender::Background(glm::vec3(1.0f)));
  const matrender::Camera camera =
      matrender::Camera::look_at({0.0, -3.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 0.6, 24, 20);
  matrender::RenderSettings settings;
  settings.samples_per_pixel = 4;
  settings.aovs = matrender::AovDepth;  // the denoiser's guides are added to what is asked for
  settings.denoise = matrender::Denoising::Learned;
  matrender::FrameBuffers frame;
  matrender::provide_learned_denoiser(nullptr);
  CATCH_CHECK_THROWS_WITH(matrender::render(scene, camera, settings, frame),
                          Catch::Contains("render: denoise: \"learned\" needs the learned denoiser"));

  const auto denoiser = std::make_shared<LearnedDenoiser>(seeded_network(9));
  matrender::provide_learned_denoiser(denoiser);
  matrender::render(scene, camera, settings, frame);
  matrender::provide_learned_denoiser(nullptr);
  CATCH_CHECK((frame.aovs & denoiser->guide_aovs()) == denoiser->guide_aovs());
  CATCH_CHECK(finite_non_negative(frame.color));
  // The same as denoising the raw render by hand.
  settings.denoise = matrender::Denoising::Off;
  settings.aovs |= denoiser->guide_aovs();
  matrender::FrameBuffers raw;
  matrender::render(scene, camera, settings, raw);
  denoiser->denoise(raw, 0);
  CATCH_CHECK(raw.color == frame.color);
}
