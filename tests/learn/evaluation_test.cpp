// Evaluation (matlearn/evaluation/*): a network whose output is known (its head zeroed, so every
// map is sigmoid(0) = 0.5) scored on the four-image dataset, against the metrics' closed forms;
// the tables per material and per object, the report files and the panels.
// libtorch includes glog, whose CHECK would replace Catch's: Catch's macros go by CATCH_ names.
#define CATCH_CONFIG_PREFIX_ALL
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <OpenImageIO/imageio.h>

#include "matbase/pi.h"
#include "matlearn/evaluation/evaluator.h"
#include "matlearn/evaluation/inference.h"
#include "matlearn/evaluation/panels.h"
#include "matlearn/evaluation/report.h"
#include "matlearn/training/trainer.h"
#include "training_dataset.h"

using namespace matlearn;
namespace fs = std::filesystem;

namespace {

// A checkpoint of the quarter-width UNet-no-skip with its head zeroed.
fs::path half_grey_checkpoint() {
  TrainingConfig c = training_dataset::quick_config("matpredict_evaluation_test");
  c.epochs = 1;
  Trainer trainer(c);
  CATCH_REQUIRE(trainer.train());
  const CheckpointHeader header = read_checkpoint(c.output_dir / "checkpoints" / "last.pt").header;
  {
    torch::NoGradGuard no_grad;
    for (auto& p : trainer.model().named_parameters())
      if (p.key().rfind("head.", 0) == 0) p.value().zero_();
  }
  torch::optim::Adam unused(trainer.model().parameters());
  const fs::path path = c.output_dir / "half_grey.pt";
  save_checkpoint(path, header, trainer.model(), unused);
  return path;
}

}  // namespace

CATCH_TEST_CASE("Evaluation scores the sigmoid maps against the truth, whole and per material", "[learn]") {
  const fs::path checkpoint = half_grey_checkpoint();
  const Checkpoint file = read_checkpoint(checkpoint);
  const CheckpointHeader& header = file.header;
  const auto model = load_model(file);
  const fs::path root = training_dataset::four_image_dataset();
  const std::vector<matdataset::SampleId> samples = matdataset::index_dataset(root);
  EvaluationSettings settings;
  settings.threads = 1;
  const EvaluationResult result = evaluate_samples(*model, header, root, samples, settings);
  // 4 samples x 2 maps, whole object and its one family.
  CATCH_REQUIRE(result.scores.size() == 16);
  for (const ScoredMap& s : result.scores) {
    const int k = training_dataset::sample_index(s.sample);
    if (s.map == "base_color") {
      // RMSE of 0.5 against the constant albedo, and the angle between it and grey.
      double squared = 0.0, dot = 0.0, norm = 0.0;
      for (int c = 0; c < 3; ++c) {
        const double a = training_dataset::kAlbedo[k][c] / 255.0;
        squared += (a - 0.5) * (a - 0.5) / 3.0;
        dot += a * 0.5;
        norm += a * a;
      }
      CATCH_CHECK(s.scores[Metric::rmse] == Catch::Detail::Approx(std::sqrt(squared)).epsilon(1e-5));
      CATCH_CHECK(s.scores[Metric::sam] ==
                  Catch::Detail::Approx(std::acos(dot / std::sqrt(norm * 0.75)) * 180.0 / matbase::kPi).epsilon(1e-4));
    } else {
      CATCH_CHECK(s.map == "roughness");
      const double r = training_dataset::kRoughness[k] / 255.0;
      CATCH_CHECK(s.scores[Metric::rmse] == Catch::Detail::Approx(std::abs(r - 0.5)).epsilon(1e-5));
      CATCH_CHECK(s.scores[Metric::psnr] == Catch::Detail::Approx(-20.0 * std::log10(std::abs(r - 0.5))).epsilon(1e-5));
    }
    CATCH_CHECK(s.pixels > 300);
    CATCH_CHECK((s.material == kWholeObject || s.material == k % 3 + 1));
  }

  const std::vector<ReportTable> tables = report_tables(result.scores);
  CATCH_REQUIRE(tables.size() == 3);
  CATCH_CHECK(tables[0].rows.size() == 3 * 2);  // families 1, 2, 3 (concrete, fabric, leather) x 2 maps
  CATCH_CHECK(tables[0].rows[0].group == "concrete");
  CATCH_CHECK(tables[1].rows.size() == 2 * 2);  // object_0, object_1
  CATCH_CHECK(tables[2].rows.size() == 2);
  CATCH_CHECK(tables[2].rows[0].maps_scored == 4);

  const fs::path out = fs::temp_directory_path() / "matpredict_evaluation_report";
  fs::remove_all(out);
  write_report(out, tables, "# test");
  std::ifstream csv(out / "metrics.csv");
  std::string header_line;
  std::getline(csv, header_line);
  CATCH_CHECK(header_line == "table,group,map,maps_scored,RMSE,PSNR,SRE,SSIM,FSIM,UIQ,SAM,ISSM");
  int rows = 0;
  for (std::string row; std::getline(csv, row);) ++rows;
  CATCH_CHECK(rows == 12);
  CATCH_CHECK(fs::exists(out / "metrics.md"));
  CATCH_CHECK(fs::exists(out / "metrics.json"));

  write_panel(out / "panels" / "concrete.png", result.samples_by_material.at(1));
  auto panel = OIIO::ImageInput::open((out / "panels" / "concrete.png").string());
  CATCH_REQUIRE(panel);
  CATCH_CHECK(panel->spec().width == 4 * training_dataset::kSize);
  CATCH_CHECK(panel->spec().height == 2 * training_dataset::kSize);
}

CATCH_TEST_CASE("A sample the object is in no pixel of is not scored, and named; none at all is an error", "[learn]") {
  const Checkpoint file = read_checkpoint(half_grey_checkpoint());
  const auto model = load_model(file);
  const fs::path root = fs::temp_directory_path() / "matpredict_evaluation_empty";
  fs::remove_all(root);
  fs::copy(training_dataset::four_image_dataset(), root, fs::copy_options::recursive);
  const auto empty_label = [&](const std::string& variant) {
    write_synthetic_png(root / variant / "label" / "000.png", training_dataset::kSize, 1,
                        [](int, int, int) -> uint8_t { return 0; });
  };
  empty_label("object_1/var000");
  const std::vector<matdataset::SampleId> samples = matdataset::index_dataset(root);
  EvaluationSettings settings;
  settings.threads = 1;
  const EvaluationResult result = evaluate_samples(*model, file.header, root, samples, settings);
  CATCH_REQUIRE(result.empty_samples.size() == 1);
  CATCH_CHECK(result.empty_samples[0].str() == "object_1/var000/000");
  CATCH_CHECK(result.scores.size() == 12);  // the other three, 2 maps x (whole, family)
  for (const char* variant : {"object_0/var000", "object_0/var001", "object_1/var001"}) empty_label(variant);
  CATCH_CHECK_THROWS_WITH(evaluate_samples(*model, file.header, root, samples, settings),
                          Catch::Contains("none of the 4 samples") && Catch::Contains("nothing to score"));
}

CATCH_TEST_CASE("Inference predicts every map of one image at the network's size", "[learn]") {
  const fs::path checkpoint = half_grey_checkpoint();
  const Checkpoint file = read_checkpoint(checkpoint);
  const CheckpointHeader& header = file.header;
  const auto model = load_model(file);
  const matbase::FloatImage rgb(training_dataset::kSize, training_dataset::kSize, 3, 0.3f);
  const PredictedMaps predicted = predict_maps(*model, header, rgb);
  CATCH_REQUIRE(predicted.names == std::vector<std::string>{"base_color", "roughness"});
  CATCH_CHECK(predicted.maps[1].channels == 3);
  for (const matbase::FloatImage& map : predicted.maps) {
    CATCH_CHECK(map.width == training_dataset::kSize);
    CATCH_CHECK(std::all_of(map.values.begin(), map.values.end(), [](float v) { return v == 0.5f; }));
  }
  const fs::path strip = fs::temp_directory_path() / "matpredict_inference_strip.png";
  write_prediction_strip(strip, rgb, matbase::Mask(rgb.pixel_count(), 1), predicted);
  auto in = OIIO::ImageInput::open(strip.string());
  CATCH_REQUIRE(in);
  CATCH_CHECK(in->spec().width == 3 * training_dataset::kSize);
}
