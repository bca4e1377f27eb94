// evaluate: scores a trained regressor on a dataset split with the paper's eight metrics and
// writes tables per material and per object, and a panel per material.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <memory>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "common/command_line.h"
#include "common/exit_codes.h"
#include "common/number_options.h"
#include "common/progress_bar.h"
#include "common/thread_count.h"
#include "matbase/file/atomic_file.h"
#include "matbase/image/image_writing.h"
#include "matbase/input_error.h"
#include "matdataset/format/dataset_error.h"
#include "matdataset/format/dataset_index.h"
#include "matdataset/format/sample_loader.h"
#include "matdataset/format/sample_reader.h"
#include "matlearn/evaluation/evaluator.h"
#include "matlearn/evaluation/inference.h"
#include "matlearn/evaluation/panels.h"
#include "matlearn/evaluation/report.h"
#include "matlearn/evaluation/segmenter_choice.h"
#include "matlearn/isolation/object_isolation.h"
#include "matlearn/training/checkpoint.h"
#include "matmaterial/material_classes.h"
#include "prompt_options.h"

namespace {

struct Options {
  std::filesystem::path checkpoint = "train_output/checkpoints/best.pt";
  std::filesystem::path dataset_root;
  std::filesystem::path split_file;
  std::string split = "test";
  uint64_t seed = 42;
  bool paper_compat = false;
  std::filesystem::path output_dir = "evaluation_output";
  int batch_size = 8;
  int threads = 0;
  std::filesystem::path image;  // inference on one image instead of a split
  std::filesystem::path mask;
  std::string box;                  // with --image and no mask: the prompt
  std::vector<std::string> points;
  std::string segmenter = "grabcut";
  std::string background = "black";
};

std::vector<matdataset::SampleId> samples_to_score(const Options& o) {
  if (!o.split_file.empty()) {
    return matdataset::split_samples(matdataset::read_split_file(o.split_file), o.split, o.dataset_root);
  }
  // train_regressor's split without a split file: whole variant folders, 80/20 by the seed.
  const auto parts = matdataset::split_by_variant(matdataset::index_dataset(o.dataset_root), matdataset::SplitRatios{}, o.seed);
  return o.split == "train" ? parts[0] : parts[1];
}

// How many samples were not scored for having no object pixel, and which (the first `named`, or
// all when `named` is 0); empty when every sample was scored.
std::string unscored_text(const matlearn::EvaluationResult& result, size_t total, int image_size, size_t named) {
  const std::vector<matdataset::SampleId>& empty = result.empty_samples;
  if (empty.empty()) return "";
  std::string text = fmt::format("{} of {} samples {} not scored: the object covers no pixel of {} at {} x {} px, "
                                 "where the metrics are undefined:",
                                 empty.size(), total, empty.size() == 1 ? "was" : "were",
                                 empty.size() == 1 ? "it" : "them", image_size, image_size);
  const size_t shown = named == 0 ? empty.size() : std::min(named, empty.size());
  for (size_t i = 0; i < shown; ++i) text += (i ? ", " : " ") + empty[i].str();
  if (shown < empty.size()) text += fmt::format(" and {} more", empty.size() - shown);
  return text;
}

std::string file_name(const std::string& text) {
  std::string name = text;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-') c = '_';
  return name;
}

matlearn::Prompt prompt_of(const Options& o) {
  matlearn::Prompt prompt;
  if (!o.box.empty()) prompt.box = evaluate_app::parse_box(o.box);
  for (const std::string& point : o.points) prompt.points.push_back(evaluate_app::parse_point(point));
  return prompt;
}

// The object in the image: the mask --mask or the image's alpha gives, else the segmenter's for
// the prompt. Says which on the console.
matlearn::IsolatedObject isolated_object(const Options& o, const matlearn::Prompt& prompt, const matdataset::PhotoInput& photo,
                                         int size) {
  const matdataset::CropBackground background =
      o.background == "white" ? matdataset::CropBackground::White : matdataset::CropBackground::Black;
  if (photo.mask) {
    const std::string source = o.mask.empty() ? "its alpha" : o.mask.string();
    if (!prompt.empty()) fmt::print(stderr, "evaluate: the mask is {}: --box and --point are not used\n", source);
    if (std::none_of(photo.mask->begin(), photo.mask->end(), [](uint8_t v) { return v != 0; }))
      throw matbase::InputError(o.image.string() + ": the mask (" + source + ") marks no pixel of the object");
    fmt::print("object: the mask of {}\n", source);
    return {*photo.mask, matdataset::isolated_input(photo.rgb, *photo.mask, size, background)};
  }
  const std::unique_ptr<matlearn::Segmenter> segmenter = matlearn::make_segmenter(o.segmenter);
  matlearn::IsolatedObject object = matlearn::isolate_object(photo.rgb, prompt, *segmenter, size, background, o.image.string());
  const matbase::PixelBox box = prompt.box ? *prompt.box : *matlearn::default_prompt(photo.rgb.width, photo.rgb.height).box;
  fmt::print("object: {} in the box ({},{})-({},{}){}, {} px of {} x {}\n", segmenter->name(), box.x0, box.y0, box.x1,
             box.y1, prompt.points.empty() ? "" : fmt::format(" and {} points", prompt.points.size()),
             std::count(object.mask.begin(), object.mask.end(), 1), photo.rgb.width, photo.rgb.height);
  return object;
}

// Inference: the object isolated and cropped to the network's size, its maps and a strip of them.
int predict(const Options& o, const matlearn::Prompt& prompt, const matlearn::CheckpointHeader& header,
            matlearn::RegressorImpl& model) {
  matdataset::PhotoInput photo;
  try {
    photo = matdataset::read_photo(o.image, o.mask);
  } catch (const std::runtime_error& e) {
    throw matbase::InputError(e.what());
  }
  const matlearn::IsolatedObject object = isolated_object(o, prompt, photo, header.image_size);
  const matdataset::InputImage& input = object.isolated.input;
  const matlearn::PredictedMaps predicted = matlearn::predict_maps(model, header, input.rgb);
  std::string written;
  matbase::OutputFolder folder(o.output_dir);
  matbase::AtomicFileSet files(o.output_dir / "panel.png");
  std::vector<float> mask(object.mask.begin(), object.mask.end());
  matbase::write_data_png((o.output_dir / "mask.png").string(), photo.rgb.width, photo.rgb.height, 1, mask.data(), 255.0,
                          0.0, false, &files);
  matbase::write_data_png((o.output_dir / "input.png").string(), input.rgb.width, input.rgb.height, 3,
                          input.rgb.values.data(), 255.0, 0.0, false, &files);
  for (size_t m = 0; m < predicted.maps.size(); ++m) {
    matlearn::write_map_png(o.output_dir / (predicted.names[m] + ".png"), predicted.maps[m], input.mask, &files);
    written += predicted.names[m] + ".png, ";
  }
  matlearn::write_prediction_strip(o.output_dir / "panel.png", input.rgb, input.mask, predicted, &files);
  files.commit();
  folder.keep();
  const matbase::CropSquare& crop = object.isolated.crop;
  fmt::print("wrote {}: mask.png (the object, {} x {}), input.png (the {} px square at ({}, {}) on {}, resized to {} x {}), "
             "{}panel.png (input | maps); off the object the maps are black\n",
             o.output_dir.string(), photo.rgb.width, photo.rgb.height, crop.side, crop.left, crop.top, o.background,
             header.image_size, header.image_size, written);
  return 0;
}

int run(const Options& o) {
  if (o.image.empty() && (!o.box.empty() || !o.points.empty() || !o.mask.empty()))
    throw matbase::InputError("--box, --point and --mask describe the object of --image; give --image");
  const matlearn::Prompt prompt = prompt_of(o);  // refused before the checkpoint is read
  std::filesystem::path checkpoint = o.checkpoint;
  // train_regressor writes best.pt only when it validated; last.pt always.
  if (!std::filesystem::exists(checkpoint) && checkpoint.filename() == "best.pt" &&
      std::filesystem::exists(checkpoint.parent_path() / "last.pt"))
    checkpoint = checkpoint.parent_path() / "last.pt";
  matlearn::CheckpointHeader header;
  std::shared_ptr<matlearn::RegressorImpl> model;
  try {
    const matlearn::Checkpoint file = matlearn::read_checkpoint(checkpoint);
    header = file.header;
    model = matlearn::load_model(file);
  } catch (const std::runtime_error& e) {
    throw matbase::InputError(e.what());
  }
  if (header.layout.regression_channels() == 0) throw matbase::InputError(checkpoint.string() + " predicts no maps");
  if (!o.image.empty()) return predict(o, prompt, header, *model);
  if (o.dataset_root.empty()) throw matbase::InputError("give --dataset-root to score a split, or --image to predict one image");
  std::vector<matdataset::SampleId> samples;
  try {
    samples = samples_to_score(o);
  } catch (const std::runtime_error& e) {
    if (dynamic_cast<const matbase::InputError*>(&e)) throw;
    throw matbase::InputError(e.what());
  }
  if (samples.empty()) throw matbase::InputError("the " + o.split + " split of " + o.dataset_root.string() + " is empty");
  fmt::print("scoring {} ({} epochs) on {} {} samples, {} metrics\n", header.network, header.epochs_done,
             samples.size(), o.split, o.paper_compat ? "paper-compatible" : "correct");
  std::fflush(stdout);

  matlearn::EvaluationSettings settings;
  settings.convention = o.paper_compat ? matlearn::MetricConvention::paper_compat : matlearn::MetricConvention::correct;
  settings.batch_size = o.batch_size;
  settings.threads = app_support::announced_worker_threads("evaluate", "--threads", o.threads);
  app_support::ProgressBar bar("evaluate");
  matlearn::EvaluationResult result;
  try {
    result = matlearn::evaluate_samples(
        *model, header, o.dataset_root, samples, settings,
        [&bar](size_t done, size_t total) { bar.update(static_cast<double>(done) / static_cast<double>(total)); });
  } catch (...) {
    bar.finish();  // the error's line below the bar's, not on it
    throw;
  }
  bar.finish();
  // The console names the first few; the report, which is the record, all of them.
  if (const std::string unscored = unscored_text(result, samples.size(), header.image_size, 5); !unscored.empty())
    fmt::print(stderr, "evaluate: warning: {}\n", unscored);

  const std::string convention =
      o.paper_compat
          ? "paper-compatible: image-similarity-measures' conventions on 8-bit maps (RMSE and PSNR with max_p 4095, "
            "its SAM), background set to 0, whole images; only for comparing with the paper"
          : "correct: float maps in [0, 1], data range 1, only the object's pixels (each family's pixels in the "
            "material table); SAM in degrees, - for one-channel maps";
  const std::string unscored = unscored_text(result, samples.size(), header.image_size, 0);
  const std::string preamble = fmt::format(
      "# Evaluation of {}\n\nCheckpoint `{}` ({}, {} epochs, {} px), {} split of `{}`: {} samples, {} scored.{}\n"
      "Metrics: {}. Predictions are the sigmoid of the network's output, as in training.\n",
      header.network, checkpoint.string(), header.network, header.epochs_done, header.image_size, o.split,
      o.dataset_root.string(), samples.size(), samples.size() - result.empty_samples.size(),
      unscored.empty() ? "" : "\n" + unscored, convention);
  const std::vector<matlearn::ReportTable> tables = matlearn::report_tables(result.scores);
  // The tables and panels appear together or not at all; the tables last, as readers open them.
  matbase::OutputFolder folder(o.output_dir), panels(o.output_dir / "panels");
  matbase::AtomicFileSet files(o.output_dir / "metrics.json");
  for (const auto& [material, sample] : result.samples_by_material)
    matlearn::write_panel(o.output_dir / "panels" /
                              (file_name(material == matlearn::kWholeObject ? "object" : matmaterial::label_name(material)) +
                               ".png"),
                          sample, &files);
  matlearn::write_report(o.output_dir, tables, preamble, &files);
  files.commit();
  panels.keep();
  folder.keep();

  for (const matlearn::ReportRow& row : tables.back().rows)
    fmt::print("{:<12} RMSE {:.4f}  PSNR {:.2f}  SSIM {:.4f}  FSIM {:.4f}  SAM {:.2f}\n", row.map,
               row.mean[matlearn::Metric::rmse], row.mean[matlearn::Metric::psnr], row.mean[matlearn::Metric::ssim],
               row.mean[matlearn::Metric::fsim], row.mean[matlearn::Metric::sam]);
  fmt::print("wrote {}: metrics.md, metrics.csv, metrics.json (by material, by object, overall), panels/ "
             "(input | truth | prediction | error x4 per map, one per material)\n",
             o.output_dir.string());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Scores a network trained by train_regressor on a dataset split with the paper's eight metrics (RMSE, "
               "PSNR, SRE, SSIM, FSIM, UIQ, SAM, ISSM) and writes tables per material and per object (markdown, CSV, "
               "JSON) and one PNG panel per material; or, with --image, predicts one image's maps.",
               "evaluate"};
  Options o;
  app.add_option("--checkpoint", o.checkpoint, "checkpoint train_regressor wrote (falls back to last.pt beside a missing best.pt)")
      ->capture_default_str();
  app.add_option("--dataset-root", o.dataset_root, "dataset folder in the MatPredict layout");
  app.add_option("--image", o.image, "predict the maps of this one image instead (PNG, JPEG, EXR...)")
      ->check(CLI::ExistingFile);
  app.add_option("--mask", o.mask, "with --image: the object's mask (any nonzero value; a label map works); "
                                   "default the image's alpha where some pixel is transparent, else the segmenter's")
      ->check(CLI::ExistingFile);
  app.add_option("--box", o.box, "with --image: X0,Y0,X1,Y1, the first and last pixel column and row of a box around the "
                                 "object (default: the image's central 90 %)");
  app.add_option("--point", o.points, "with --image: X,Y, a pixel on the object, or X,Y,0 one off it (repeatable)");
  app.add_option("--segmenter", o.segmenter, "with --image and no mask: what finds the object: grabcut (OpenCV's GrabCut, "
                                             "no weights) or sam:CHECKPOINT (Segment Anything, ViT-B or MobileSAM, "
                                             "converted by scripts/convert_segment_anything.py)")
      ->check([](const std::string& choice) { return matlearn::segmenter_choice_problem(choice).value_or(""); })
      ->capture_default_str();
  app.add_option("--background", o.background, "with --image: what the crop shows off the object: black (what networks "
                                               "trained on make_dataset's frames saw) or white (the paper's preprocessing)")
      ->check(CLI::IsMember({"black", "white"}))
      ->capture_default_str();
  app.add_option("--split-file", o.split_file, "split YAML; without one, the 80/20 variant split train_regressor used")
      ->check(CLI::ExistingFile);
  app.add_option("--split", o.split, "train, val or test (without a split file: train, or val and test alike for the 20 % part)")
      ->check(CLI::IsMember({"train", "val", "test"}))
      ->capture_default_str();
  app.add_option("--seed", o.seed, "seed of the split without a split file")
      ->check(app_support::any_seed())
      ->capture_default_str();
  app.add_flag("--paper-compat", o.paper_compat, "image-similarity-measures' conventions (8-bit, max_p 4095, its SAM), to compare with the paper");
  app.add_option("--output-dir", o.output_dir, "folder for the tables and panels")->capture_default_str();
  app.add_option("--batch-size", o.batch_size, "samples per forward pass")->check(app_support::whole_number_in(1, app_support::kMaxBatchSize))
      ->capture_default_str();
  app.add_option("--threads", o.threads, "torch and decoding threads (0: all cores; more than the machine has are capped)")
      ->check(app_support::whole_number_in(0, app_support::kMaxThreadRequest))
      ->capture_default_str();
  if (const std::optional<int> exit_code = app_support::parse_command_line(app, argc, argv, "evaluate")) return *exit_code;
  try {
    return run(o);
  } catch (const matbase::InputError& e) {
    return app_support::report_error("evaluate", e.what(), app_support::kInputError);
  } catch (const matdataset::DatasetError& e) {
    return app_support::report_error("evaluate", e.what(), app_support::kInputError);
  } catch (const std::exception& e) {
    return app_support::report_error("evaluate", e.what(), app_support::kRuntimeFailure);
  }
}
