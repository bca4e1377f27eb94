// Training (matlearn/training/*): the loss on hand-computed cases, the learning-rate schedules'
// closed forms, checkpoints, a network overfitting four images, and a resumed run that continues
// exactly as the uninterrupted one.
// libtorch includes glog, whose CHECK would replace Catch's: Catch's macros go by CATCH_ names.
#define CATCH_CONFIG_PREFIX_ALL
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>

#include "matdataset/format/dataset_index.h"
#include "matlearn/training/batch.h"
#include "matlearn/training/checkpoint.h"
#include "matlearn/training/learning_rate_schedule.h"
#include "matlearn/training/loss.h"
#include "matlearn/training/trainer.h"
#include "training_dataset.h"

using namespace matlearn;
namespace fs = std::filesystem;

namespace {

using training_dataset::quick_config;

Batch constant_batch(float target, float mask_fraction_rows) {
  Batch b;
  b.input = torch::zeros({2, 3, 4, 4});
  b.target = torch::full({2, 6, 4, 4}, target);
  b.mask = torch::zeros({2, 1, 4, 4});
  b.mask.narrow(2, 0, static_cast<int64_t>(mask_fraction_rows * 4)).fill_(1.0);
  b.labels = torch::full({2, 4, 4}, kIgnoredLabel, torch::kLong);
  return b;
}

}  // namespace

CATCH_TEST_CASE("The loss is the masked error of the sigmoid maps, weighted per map", "[learn]") {
  OutputLayout layout = OutputLayout::paper();
  layout.groups[1].weight = 0.5;
  // Logits 0 predict 0.5 everywhere; the target is 0.1 on the object rows and would be 0.9 off it.
  Batch batch = constant_batch(0.1f, 0.5f);
  batch.target.narrow(2, 2, 2).fill_(0.9f);
  const torch::Tensor zero_logits = torch::zeros({2, 6, 4, 4});
  const LossTerms mse = training_loss(zero_logits, batch, layout, RegressionLoss::mse);
  CATCH_CHECK(mse.group_terms[0] == Catch::Detail::Approx(0.16));
  CATCH_CHECK(mse.group_terms[1] == Catch::Detail::Approx(0.16));
  CATCH_CHECK(mse.total.item<double>() == Catch::Detail::Approx(0.16 + 0.5 * 0.16));
  const LossTerms l1 = training_loss(zero_logits, batch, layout, RegressionLoss::l1);
  CATCH_CHECK(l1.group_terms[0] == Catch::Detail::Approx(0.4));
  // An empty mask gives 0, not NaN.
  const LossTerms empty = training_loss(zero_logits, constant_batch(0.1f, 0.0f), layout, RegressionLoss::mse);
  CATCH_CHECK(empty.total.item<double>() == 0.0);
  // Cross-entropy of uniform logits over 4 classes is log 4 on every labelled pixel; unlabelled
  // pixels do not count, labels beyond the classes are an error.
  layout.material_classes = 4;
  batch.labels.select(0, 0).fill_(2);
  const LossTerms ce = training_loss(torch::zeros({2, 10, 4, 4}), batch, layout, RegressionLoss::mse);
  CATCH_CHECK(ce.material_term == Catch::Detail::Approx(std::log(4.0)));
  batch.labels.select(0, 1).fill_(4);
  CATCH_CHECK_THROWS_WITH(training_loss(torch::zeros({2, 10, 4, 4}), batch, layout, RegressionLoss::mse),
                          Catch::Contains("material id 4"));
}

CATCH_TEST_CASE("Output layouts are checked", "[learn]") {
  OutputLayout layout = OutputLayout::paper();
  CATCH_CHECK(layout.output_channels() == 6);
  layout.groups.push_back({MapKind::metallic, 1, 1.0});
  CATCH_CHECK(layout.output_channels() == 7);
  CATCH_CHECK(layout.first_channel(2) == 6);
  layout.groups.push_back({MapKind::roughness, 1, 1.0});
  CATCH_CHECK_THROWS_WITH(validate(layout), Catch::Contains("twice"));
  layout.groups.pop_back();
  layout.groups[0].channels = 1;
  CATCH_CHECK_THROWS_WITH(validate(layout), Catch::Contains("base_color"));
  layout.groups[0].channels = 3;
  layout.material_classes = 1;
  CATCH_CHECK_THROWS(validate(layout));
}

CATCH_TEST_CASE("Batches stack each output group's map in the layout's order", "[learn]") {
  using training_dataset::encoded_normal;
  using training_dataset::kAlbedo;
  using training_dataset::kRoughness;
  using training_dataset::sample_index;
  OutputLayout layout = OutputLayout::paper();  // base colour 3 + roughness 3
  layout.groups.push_back({MapKind::normal, 3, 1.0});
  const fs::path root = training_dataset::four_image_dataset();
  const std::vector<matdataset::SampleId> ids = matdataset::index_dataset(root);
  const matdataset::SampleSettings settings = sample_settings(layout, training_dataset::kSize, false);
  CATCH_CHECK(settings.read_normal);
  std::vector<matdataset::MaterialSample> samples;
  for (const matdataset::SampleId& id : ids) samples.push_back(matdataset::read_sample(root, id, settings));
  const Batch batch = make_batch(samples, layout, InputNormalization::none);
  CATCH_REQUIRE(batch.target.sizes() == torch::IntArrayRef({4, 9, 32, 32}));
  for (size_t i = 0; i < ids.size(); ++i) {
    const int k = sample_index(ids[i]);
    const torch::Tensor centre = batch.target[static_cast<int64_t>(i)].select(2, 16).select(1, 16);
    for (int c = 0; c < 3; ++c) {
      CATCH_CHECK(centre[c].item<float>() == Catch::Detail::Approx(kAlbedo[k][c] / 255.0));
      CATCH_CHECK(centre[3 + c].item<float>() == Catch::Detail::Approx(kRoughness[k] / 255.0));
      CATCH_CHECK(centre[6 + c].item<float>() == Catch::Detail::Approx(encoded_normal(k, c) / 255.0).margin(4e-3));
    }
  }
  // Samples read without their normal maps do not make a batch that needs them.
  std::vector<matdataset::MaterialSample> without = {matdataset::read_sample(root, ids[0], sample_settings(OutputLayout::paper(), 32, false))};
  CATCH_CHECK_THROWS_WITH(make_batch(without, layout, InputNormalization::none), Catch::Contains("normal"));
}

CATCH_TEST_CASE("Training reads the paper's texture-target layout too", "[learn]") {
  // Two materials, each a flat reference colour and roughness, and two screenshots of each.
  const fs::path root = fs::temp_directory_path() / "matpredict_paper_layout_training";
  fs::remove_all(root);
  const char* materials[] = {"fabric", "metal"};
  for (int m = 0; m < 2; ++m) {
    for (const char* object : {"chair", "vase"})
      write_synthetic_png(root / "rendered_cropped" / object / materials[m] / "000.png", 32, 3,
                          [m](int x, int, int c) -> uint8_t { return static_cast<uint8_t>(60 + 100 * m + 2 * x + 20 * c); });
    write_synthetic_png(root / "ground_truth_basecolour" / (std::string(materials[m]) + ".png"), 64, 3,
                        [m](int, int, int c) -> uint8_t { return static_cast<uint8_t>(m ? 200 - 50 * c : 40 + 60 * c); });
    write_synthetic_png(root / "ground_truth_roughness" / (std::string(materials[m]) + ".png"), 64, 1,
                        [m](int, int, int) -> uint8_t { return m ? 50 : 220; });
  }
  TrainingConfig c = quick_config("matpredict_paper_layout_output");
  c.dataset_root = root;
  c.train_samples = matdataset::index_dataset(root);
  CATCH_REQUIRE(c.train_samples.size() == 4);
  c.epochs = 60;
  c.learning_rate = 3e-3;
  Trainer trainer(c);
  CATCH_REQUIRE(trainer.train());
  // The whole image is the target: the loss falls as the network learns the two references.
  const double first = trainer.history().front().train_loss, last = trainer.history().back().train_loss;
  CATCH_INFO("loss " << first << " -> " << last);
  CATCH_CHECK(last * 2.0 < first);
}

CATCH_TEST_CASE("Learning-rate schedules follow PyTorch's closed forms", "[learn]") {
  ScheduleSettings step;  // StepLR(20, 0.5)
  ScheduleState s = start_schedule(2e-4);
  for (int e = 0; e < 19; ++e) s = finish_epoch(step, 2e-4, s, 1.0);
  CATCH_CHECK(s.rate == Catch::Detail::Approx(2e-4));
  s = finish_epoch(step, 2e-4, s, 1.0);
  CATCH_CHECK(s.rate == Catch::Detail::Approx(1e-4));
  for (int e = 0; e < 20; ++e) s = finish_epoch(step, 2e-4, s, 1.0);
  CATCH_CHECK(s.rate == Catch::Detail::Approx(5e-5));

  ScheduleSettings cosine;
  cosine.kind = ScheduleKind::cosine;
  cosine.t_max = 50;
  s = start_schedule(1e-4);
  for (int e = 0; e < 25; ++e) s = finish_epoch(cosine, 1e-4, s, 1.0);
  CATCH_CHECK(s.rate == Catch::Detail::Approx(0.5e-4));
  for (int e = 0; e < 25; ++e) s = finish_epoch(cosine, 1e-4, s, 1.0);
  CATCH_CHECK(s.rate == Catch::Detail::Approx(0.0).margin(1e-20));

  // Plateau, patience 2: improvements keep the rate; the third epoch without one halves it.
  ScheduleSettings plateau;
  plateau.kind = ScheduleKind::plateau;
  plateau.patience = 2;
  s = start_schedule(1.0);
  for (double loss : {5.0, 4.0, 4.0, 3.9999, 4.5}) s = finish_epoch(plateau, 1.0, s, loss);
  CATCH_CHECK(s.rate == 0.5);
  CATCH_CHECK(s.epochs_without_improvement == 0);
  CATCH_CHECK_THROWS_WITH(schedule_kind_named("linear"), Catch::Contains("linear"));
}

CATCH_TEST_CASE("A network overfits four images: the training loss falls tenfold", "[learn]") {
  TrainingConfig c = quick_config("matpredict_overfit_test");
  c.epochs = 200;  // one step of all four images per epoch
  c.learning_rate = 3e-3;
  c.schedule.step_size = 1000;  // a constant rate
  Trainer trainer(c);
  CATCH_REQUIRE(trainer.train());
  const double first = trainer.history().front().train_loss, last = trainer.history().back().train_loss;
  CATCH_INFO("loss " << first << " -> " << last);
  CATCH_CHECK(last * 10.0 <= first);
  CATCH_CHECK(std::isfinite(last));
  // The log has a header and one row per epoch.
  std::ifstream log(c.output_dir / "log.csv");
  std::string header;
  std::getline(log, header);
  CATCH_CHECK(header == "epoch,train_loss,train_base_color,train_roughness,train_material,validation_loss,learning_rate,seconds");
  int rows = 0;
  for (std::string row; std::getline(log, row);) ++rows;
  CATCH_CHECK(rows == 200);
}

CATCH_TEST_CASE("A resumed run continues exactly as the uninterrupted run", "[learn]") {
  // Cosine schedule, AdamW, a segmentation head and validation: every piece of state matters.
  const auto configure = [](const std::string& output, int epochs) {
    TrainingConfig c = quick_config(output);
    c.epochs = epochs;
    c.batch_size = 3;  // two steps per epoch, the second with one sample
    c.optimizer = OptimizerKind::adamw;
    c.weight_decay = 1e-2;
    c.schedule.kind = ScheduleKind::cosine;
    c.schedule.t_max = 4;
    c.layout.material_classes = 4;
    c.validation_samples = {c.train_samples[0]};
    return c;
  };
  Trainer straight(configure("matpredict_resume_straight", 4));
  CATCH_REQUIRE(straight.train());

  const TrainingConfig first_half = configure("matpredict_resume_split", 2);
  {
    Trainer interrupted(first_half);
    CATCH_REQUIRE(interrupted.train());
  }
  TrainingConfig second_half = configure("matpredict_resume_resumed", 4);
  fs::remove_all(second_half.output_dir);
  fs::copy(first_half.output_dir, second_half.output_dir, fs::copy_options::recursive);
  Trainer resumed(second_half);
  resumed.resume(second_half.output_dir / "checkpoints" / "last.pt");
  CATCH_CHECK(resumed.epochs_done() == 2);
  CATCH_REQUIRE(resumed.train());

  auto a = straight.model().named_parameters(), b = resumed.model().named_parameters();
  for (const auto& p : a) CATCH_CHECK(torch::equal(p.value(), b[p.key()]));
  auto abuf = straight.model().named_buffers(), bbuf = resumed.model().named_buffers();
  for (const auto& p : abuf) CATCH_CHECK(torch::equal(p.value(), bbuf[p.key()]));
  for (size_t e = 0; e < 2; ++e)
    CATCH_CHECK(straight.history()[e + 2].train_loss == resumed.history()[e].train_loss);
  // The resumed log holds all four epochs.
  std::ifstream log(second_half.output_dir / "log.csv");
  int lines = 0;
  for (std::string row; std::getline(log, row);) ++lines;
  CATCH_CHECK(lines == 5);
}

CATCH_TEST_CASE("A loss that becomes NaN stops training, naming the epoch and batch, and keeps the last checkpoint",
                "[learn]") {
  TrainingConfig c = quick_config("matpredict_diverged_test");
  c.epochs = 1;
  {
    Trainer first(c);
    CATCH_REQUIRE(first.train());
  }
  const fs::path last = c.output_dir / "checkpoints" / "last.pt";
  std::ifstream before_file(last, std::ios::binary);
  const std::string before((std::istreambuf_iterator<char>(before_file)), std::istreambuf_iterator<char>());
  c.epochs = 2;
  Trainer second(c);
  second.resume(last);
  {
    // What an overflowing step leaves behind: a weight that is no number.
    torch::NoGradGuard no_grad;
    second.model().parameters().front().view(-1)[0].fill_(std::nan(""));
  }
  CATCH_CHECK_THROWS_WITH(second.train(), Catch::Contains("the loss of epoch 2, batch 1 of") &&
                                              Catch::Contains("training diverged") &&
                                              Catch::Contains("learning rate"));
  std::ifstream after_file(last, std::ios::binary);
  const std::string after((std::istreambuf_iterator<char>(after_file)), std::istreambuf_iterator<char>());
  CATCH_CHECK(after == before);  // no checkpoint of the diverged epoch
  CATCH_CHECK(read_checkpoint(last).header.epochs_done == 1);
}

CATCH_TEST_CASE("Checkpoints keep the design and reject other files", "[learn]") {
  TrainingConfig c = quick_config("matpredict_checkpoint_test");
  c.epochs = 1;
  c.layout.groups.push_back({MapKind::metallic, 1, 0.25});
  c.layout.groups.push_back({MapKind::normal, 3, 2.0});
  c.linear_albedo = true;
  Trainer trainer(c);
  CATCH_REQUIRE(trainer.train());
  const fs::path last = c.output_dir / "checkpoints" / "last.pt";
  const Checkpoint checkpoint = read_checkpoint(last);
  const CheckpointHeader& header = checkpoint.header;
  CATCH_CHECK(header.network == "unet_no_skip");
  CATCH_CHECK(header.width_divisor == 4);
  CATCH_CHECK(header.layout.output_channels() == 10);
  CATCH_CHECK(header.layout.groups[2].weight == 0.25);
  CATCH_CHECK(header.layout.groups[3].map == MapKind::normal);
  CATCH_CHECK(header.layout.groups[3].weight == 2.0);
  CATCH_CHECK(header.linear_albedo);
  CATCH_CHECK(header.epochs_done == 1);
  const auto model = load_model(checkpoint);
  CATCH_CHECK(torch::equal(model->named_parameters()["head.weight"], trainer.model().named_parameters()["head.weight"]));
  std::ofstream(c.output_dir / "not_a_checkpoint.pt") << "hello";
  CATCH_CHECK_THROWS_WITH(read_checkpoint(c.output_dir / "not_a_checkpoint.pt"), Catch::Contains("not_a_checkpoint.pt"));
  // A checkpoint of another design does not resume this one.
  TrainingConfig other = quick_config("matpredict_checkpoint_other");
  other.epochs = 1;
  Trainer mismatched(other);
  CATCH_CHECK_THROWS_WITH(mismatched.resume(last), Catch::Contains("trained to predict base_color,roughness:3,"
                                                                   "metallic:1,normal (linear albedo), not the "
                                                                   "configured base_color,roughness:3"));
}

namespace {

// The file's bytes with `count` of them flipped (every bit), at positions drawn with a fixed seed
// from the middle half of the file, where the weights are.
void flip_bytes(const fs::path& from, const fs::path& to, int count) {
  std::ifstream in(from, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::mt19937 random(7);
  std::uniform_int_distribution<size_t> position(bytes.size() / 4, 3 * bytes.size() / 4);
  for (int i = 0; i < count; ++i) bytes[position(random)] ^= static_cast<char>(0xff);
  std::ofstream(to, std::ios::binary) << bytes;
}

}  // namespace

CATCH_TEST_CASE("A damaged checkpoint and one of another layout are refused", "[learn]") {
  TrainingConfig c = quick_config("matpredict_checkpoint_damage");
  c.epochs = 1;
  Trainer trainer(c);
  CATCH_REQUIRE(trainer.train());
  const fs::path last = c.output_dir / "checkpoints" / "last.pt";
  // Flipped bytes in the weights: torch's own reader loads such a file without complaint.
  const fs::path flipped = c.output_dir / "flipped.pt";
  flip_bytes(last, flipped, 200);
  CATCH_CHECK_THROWS_WITH(read_checkpoint(flipped), Catch::Contains("flipped.pt is damaged"));
  // One flipped byte is enough.
  flip_bytes(last, flipped, 1);
  CATCH_CHECK_THROWS_WITH(read_checkpoint(flipped), Catch::Contains("flipped.pt is damaged"));
  // Cut short, as by a copy that stopped.
  const fs::path cut = c.output_dir / "cut.pt";
  fs::copy_file(last, cut, fs::copy_options::overwrite_existing);
  fs::resize_file(cut, fs::file_size(last) / 2);
  CATCH_CHECK_THROWS_WITH(read_checkpoint(cut), Catch::Contains("cut.pt is not a checkpoint"));

  // A type annotation in the archive's TorchScript changed (the fuzzer's find): libtorch throws
  // torch::jit::ErrorReport, not c10::Error, and it must still come out as a clear refusal.
  {
    std::ifstream in(last, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const size_t at = bytes.rfind("header : str");
    CATCH_REQUIRE(at != std::string::npos);
    bytes.replace(at, 12, "header : stx");
    const fs::path retyped = c.output_dir / "retyped.pt";
    std::ofstream(retyped, std::ios::binary) << bytes;
    CATCH_CHECK_THROWS_WITH(read_checkpoint(retyped), Catch::Contains("retyped.pt is not a checkpoint: "));
  }

  // base_color + normal has the same 6 channels as the paper's base_color + roughness:3.
  TrainingConfig normal = quick_config("matpredict_checkpoint_normal");
  normal.epochs = 1;
  normal.layout.groups = {{MapKind::base_color, 3, 1.0}, {MapKind::normal, 3, 1.0}};
  Trainer normal_trainer(normal);
  CATCH_REQUIRE(normal_trainer.train());
  Trainer paper(c);
  CATCH_CHECK_THROWS_WITH(paper.resume(normal.output_dir / "checkpoints" / "last.pt"),
                          Catch::Contains("trained to predict base_color,normal, not the configured "
                                          "base_color,roughness:3"));
  // Loss weights are not part of what a channel means: fine-tuning with other weights resumes.
  TrainingConfig reweighted = c;
  reweighted.layout.groups[1].weight = 3.0;
  Trainer fine_tuned(reweighted);
  CATCH_CHECK_NOTHROW(fine_tuned.resume(last));
  CATCH_CHECK(fine_tuned.epochs_done() == 1);
}
