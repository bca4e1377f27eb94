#pragma once
// A trained regressor run over dataset samples and scored with the eight metrics, per sample and
// map, over the whole object and over each material family's pixels (label ids), as the tables
// per object and per material need.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "matbase/image/float_image.h"
#include "matdataset/format/dataset_index.h"
#include "matlearn/metric_scores.h"
#include "matlearn/models/regressor.h"
#include "matlearn/training/checkpoint.h"

namespace matlearn {

struct EvaluationSettings {
  MetricConvention convention = MetricConvention::correct;
  int batch_size = 8;
  int threads = 0;  // torch and decoding threads; 0 = all hardware threads
};

// The pixels a score covers: the whole object, or one material family's part of it.
constexpr int32_t kWholeObject = -1;

struct ScoredMap {
  matdataset::SampleId sample;
  std::string map;  // map_name of the output group
  int32_t material = kWholeObject;
  int pixels = 0;  // pixels scored
  MetricScores scores;
};

// One sample's input, truths and predictions (values in [0, 1]), for panels.
struct SamplePredictions {
  matdataset::SampleId sample;
  matbase::FloatImage input;
  matbase::Mask mask;
  std::vector<std::string> maps;
  std::vector<matbase::FloatImage> truths, predictions;
};

struct EvaluationResult {
  std::vector<ScoredMap> scores;
  // The first sample (in the given order) showing each material family.
  std::map<int32_t, SamplePredictions> samples_by_material;
  // Samples whose object covers no pixel at the network's size (an empty label map, or an
  // object too small to survive the resize): the metrics of an empty region are undefined, so
  // they are not scored, and a report must say so.
  std::vector<matdataset::SampleId> empty_samples;
};

// A family's part of an object must have at least this many pixels to be scored on its own
// (SSIM's 7x7 window needs room).
constexpr int kMinimumMaterialPixels = 49;

// Runs `model` (built from `header`) in evaluation mode over `samples` under `root`. The maps
// are the sigmoid of the regression channels, as in training. Samples without a label file are
// scored over the whole image; samples whose object covers no pixel are listed in
// empty_samples instead. Uses matlearn's tensor memory cache (training/tensor_memory_cache.h).
// progress(done, total) follows each batch. Throws DatasetError (matdataset/format/dataset_error.h)
// naming the files when the samples lack a map the network needs (require_sample_files) or a
// map cannot be read, and when no sample has an object pixel.
EvaluationResult evaluate_samples(RegressorImpl& model, const CheckpointHeader& header, const std::filesystem::path& root,
                                  const std::vector<matdataset::SampleId>& samples, const EvaluationSettings& settings,
                                  const std::function<void(size_t, size_t)>& progress = {});

}  // namespace matlearn
