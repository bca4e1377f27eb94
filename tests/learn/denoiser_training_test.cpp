// Training the learned denoiser: the loss and the learning rate against their closed forms, pairs
// read from datasets make_dataset renders here as the renderer's AOVs hold them, and a run
// stopped and continued from its checkpoint ending with the weights of one that was not.
#define CATCH_CONFIG_PREFIX_ALL
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "matbase/image/srgb.h"
#include "matdataset/format/decoded_image.h"
#include "matdataset/maker/example_pairs.h"
#include "matlearn/denoising/denoiser_pairs.h"
#include "matlearn/denoising/denoiser_training.h"
#include "matlearn/denoising/hdr_transfer.h"
#include "matlearn/models/state_dict.h"

namespace fs = std::filesystem;
using namespace matlearn;

namespace {

// The example pairs at 32 px (2 samples against 64), rendered once per test run.
const matdataset::ExamplePairs& example_pairs() {
  static const matdataset::ExamplePairs pairs = [] {
    const fs::path root = fs::temp_directory_path() / "matpredict_denoiser_pairs";
    fs::remove_all(root);
    return matdataset::render_example_pairs(root, 32, 64, 2);
  }();
  return pairs;
}

// hdr_transfer.h's equation 1, written out: ln(1 + 256 v) / ln(1 + 256 x 65504).
double equation_1(double v) { return std::log1p(256.0 * std::clamp(v, 0.0, 65504.0)) / std::log1p(256.0 * 65504.0); }

DenoiserTrainingSettings small_run(const fs::path& weights) {
  DenoiserTrainingSettings settings;
  settings.reference = example_pairs().reference;
  settings.noisy = {example_pairs().noisy};
  settings.weights = weights;
  settings.steps = 4;
  settings.batch = 2;
  settings.crop = 32;
  settings.checkpoint_every = 2;
  settings.threads = 1;
  return settings;
}

}  // namespace

CATCH_TEST_CASE("The denoiser's loss is half the L1 and half the L1 of the neighbour differences", "[learn]") {
  // 1 x 1 x 2 x 2: output [[1, 2], [3, 5]], target 0: L1 = 11 / 4; dx: (1, 2), dy: (2, 3), means 1.5 and 2.5.
  const torch::Tensor output = torch::tensor({1.0f, 2.0f, 3.0f, 5.0f}).reshape({1, 1, 2, 2});
  const torch::Tensor target = torch::zeros({1, 1, 2, 2});
  CATCH_CHECK(denoiser_loss(output, target).item<double>() == Approx(0.5 * 11.0 / 4.0 + 0.5 * (1.5 + 2.5)));
  CATCH_CHECK(denoiser_loss(target, target).item<double>() == 0.0);
}

CATCH_TEST_CASE("The learning rate warms up over 2 % of the steps, then falls along half a cosine to 1 %", "[learn]") {
  DenoiserTrainingSettings s;
  s.steps = 1001;  // 20 steps of warm-up, then 980 intervals down to the last step, 1000
  s.learning_rate = 1e-3;
  CATCH_CHECK(denoiser_learning_rate(s, 0) == Approx(1e-3 / 20));
  CATCH_CHECK(denoiser_learning_rate(s, 19) == Approx(1e-3));
  CATCH_CHECK(denoiser_learning_rate(s, 20) == Approx(1e-3));
  CATCH_CHECK(denoiser_learning_rate(s, 1000) == Approx(1e-5));
  // Halfway down the cosine: the mean of the peak and the floor.
  CATCH_CHECK(denoiser_learning_rate(s, 510) == Approx(0.5 * (1e-3 + 1e-5)));
}

CATCH_TEST_CASE("A training pair holds the noisy frame's maps as the renderer's AOVs and the reference's colour", "[learn]") {
  const std::vector<matdataset::SampleId> frames = paired_frames(example_pairs().reference, {example_pairs().noisy});
  CATCH_REQUIRE(frames.size() == 8);
  const matdataset::SampleId& id = frames[0];
  const DenoiserPair pair = read_denoiser_pair(example_pairs().noisy, example_pairs().reference, id);
  CATCH_REQUIRE(pair.input.sizes() == torch::IntArrayRef({9, 32, 32}));
  CATCH_REQUIRE(pair.target.sizes() == torch::IntArrayRef({3, 32, 32}));
  const fs::path noisy = example_pairs().noisy / id.object / id.variant;
  const matbase::FloatImage color = matdataset::decode(noisy / "images_hdr" / (id.stem + ".exr"));
  const matbase::FloatImage albedo = matdataset::decode(noisy / "albedo" / (id.stem + ".png"));
  const matbase::FloatImage reference =
      matdataset::decode(example_pairs().reference / id.object / id.variant / "images_hdr" / (id.stem + ".exr"));
  std::vector<float> rgb;
  for (size_t p = 0; p < color.values.size() / 4; ++p)
    for (size_t c = 0; c < 3; ++c) rgb.push_back(color.values[4 * p + c]);
  const float exposure = auto_exposure(rgb.data(), 32, 32);
  size_t covered = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      const float coverage = albedo.at(x, y, 3);
      covered += coverage > 0.0f;
      for (int c = 0; c < 3; ++c) {
        CATCH_CHECK(pair.input[c][y][x].item<float>() == Approx(equation_1(exposure * color.at(x, y, c))).margin(1e-6));
        CATCH_CHECK(pair.input[3 + c][y][x].item<float>() ==
                    Approx(matbase::srgb_to_linear(albedo.at(x, y, c)) * coverage).margin(1e-6));
        CATCH_CHECK(pair.target[c][y][x].item<float>() == Approx(equation_1(exposure * reference.at(x, y, c))).margin(1e-6));
      }
    }
  CATCH_CHECK(covered > 0);
  // A noisy dataset that is not there, or holds none of the reference's frames: refused, named.
  CATCH_CHECK_THROWS_WITH(paired_frames(example_pairs().reference, {example_pairs().reference.parent_path() / "nowhere"}),
                          Catch::Contains("nowhere"));
  const fs::path empty = example_pairs().reference.parent_path() / "empty";
  fs::create_directories(empty);
  CATCH_CHECK_THROWS_WITH(paired_frames(example_pairs().reference, {empty}),
                          Catch::Contains("no frame of it is in every noisy dataset"));
}

CATCH_TEST_CASE("A training run stopped and continued from its checkpoint ends with the same weights", "[learn]") {
  const fs::path dir = fs::temp_directory_path() / "matpredict_denoiser_training";
  fs::remove_all(dir);
  fs::create_directories(dir);
  CATCH_REQUIRE(train_denoiser(small_run(dir / "whole.pt"), {}));

  // Cancelled at its first report (after the checkpoint of step 2), then started again.
  std::atomic<bool> cancel{false};
  std::vector<DenoiserTrainingProgress> reports;
  const auto record = [&](const DenoiserTrainingProgress& p) {
    reports.push_back(p);
    cancel = true;
  };
  CATCH_REQUIRE_FALSE(train_denoiser(small_run(dir / "parts.pt"), record, &cancel));
  CATCH_REQUIRE(reports.size() == 1);
  CATCH_CHECK(reports[0].step == 2);
  CATCH_CHECK(std::isfinite(reports[0].loss));
  cancel = false;
  reports.clear();
  CATCH_REQUIRE(train_denoiser(small_run(dir / "parts.pt"), [&](const DenoiserTrainingProgress& p) { reports.push_back(p); }));
  CATCH_REQUIRE(reports.size() == 1);
  CATCH_CHECK(reports[0].resumed);
  CATCH_CHECK(reports[0].step == 4);

  const auto whole = read_state_dict(dir / "whole.pt"), parts = read_state_dict(dir / "parts.pt");
  CATCH_REQUIRE(whole.size() == parts.size());
  for (const auto& [name, tensor] : whole) {
    CATCH_CAPTURE(name);
    CATCH_CHECK(torch::equal(tensor, parts.at(name)));
  }
  // Other settings do not continue this checkpoint.
  DenoiserTrainingSettings other = small_run(dir / "parts.pt");
  other.steps = 6;
  CATCH_CHECK_THROWS_WITH(train_denoiser(other, {}), Catch::Contains("made by a run with other settings"));
}
