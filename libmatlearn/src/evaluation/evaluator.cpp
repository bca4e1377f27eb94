#include "matlearn/evaluation/evaluator.h"

#include "matbase/threads.h"
#include "matdataset/format/dataset_error.h"
#include "matdataset/format/sample_loader.h"
#include "matlearn/training/batch.h"
#include "matlearn/training/loss.h"
#include "matlearn/training/tensor_memory_cache.h"

namespace matlearn {
namespace {

int count(const matbase::Mask& mask) {
  int n = 0;
  for (uint8_t m : mask) n += m != 0;
  return n;
}

}  // namespace

EvaluationResult evaluate_samples(RegressorImpl& model, const CheckpointHeader& header, const std::filesystem::path& root,
                                  const std::vector<matdataset::SampleId>& samples, const EvaluationSettings& settings,
                                  const std::function<void(size_t, size_t)>& progress) {
  const int threads = matbase::worker_threads(settings.threads);
  use_tensor_memory_cache();
  torch::set_num_threads(threads);
  matdataset::LoaderSettings loader_settings;
  loader_settings.sample = sample_settings(header.layout, header.image_size, header.linear_albedo);
  loader_settings.batch_size = settings.batch_size;
  loader_settings.shuffle = false;
  loader_settings.threads = threads;
  matdataset::require_sample_files(root, samples, loader_settings.sample, "the samples to score under " + root.string());
  const matdataset::SampleLoader loader(root, samples, loader_settings);
  const InputNormalization normalization = info(architecture_named(header.network).architecture).input_normalization;
  const OutputLayout& layout = header.layout;

  EvaluationResult result;
  model.eval();
  torch::NoGradGuard no_grad;
  size_t done = 0;
  for (size_t b = 0; b < loader.batch_count(); ++b) {
    const std::vector<matdataset::MaterialSample> batch_samples = loader.batch(0, b);
    const Batch batch = make_batch(batch_samples, layout, normalization);
    const torch::Tensor maps = predicted_maps(model.forward(batch.input), layout);
    for (size_t i = 0; i < batch_samples.size(); ++i) {
      const matdataset::MaterialSample& s = batch_samples[i];
      const matdataset::SampleId& id = loader.samples()[done + i];
      if (count(s.mask) == 0) {
        result.empty_samples.push_back(id);
        continue;
      }
      SamplePredictions predictions{id, s.input, s.mask, {}, {}, {}};
      for (size_t g = 0; g < layout.groups.size(); ++g) {
        predictions.maps.push_back(map_name(layout.groups[g].map));
        predictions.truths.push_back(target_map(s, layout.groups[g]));
        predictions.predictions.push_back(to_hwc(maps[static_cast<int64_t>(i)].narrow(0, layout.first_channel(g), layout.groups[g].channels)));
      }
      // The whole object, then each family present in the label.
      std::map<int32_t, matbase::Mask> regions = {{kWholeObject, s.mask}};
      if (s.has_label)
        for (size_t p = 0; p < s.material_id.size(); ++p)
          if (s.mask[p] && s.material_id[p] > 0) {
            matbase::Mask& region = regions[s.material_id[p]];
            if (region.empty()) region.assign(s.mask.size(), 0);
            region[p] = 1;
          }
      for (const auto& [material, region] : regions) {
        const int pixels = count(region);
        if (material != kWholeObject && pixels < kMinimumMaterialPixels) continue;
        for (size_t g = 0; g < layout.groups.size(); ++g)
          result.scores.push_back({id, predictions.maps[g], material, pixels,
                                   score_map(predictions.truths[g], predictions.predictions[g], region, settings.convention)});
        if (material != kWholeObject && !result.samples_by_material.count(material))
          result.samples_by_material.emplace(material, predictions);
      }
      if (!s.has_label && !result.samples_by_material.count(kWholeObject))
        result.samples_by_material.emplace(kWholeObject, predictions);
    }
    done += batch_samples.size();
    if (progress) progress(done, loader.sample_count());
  }
  if (result.scores.empty())
    throw matdataset::DatasetError("none of the " + std::to_string(samples.size()) + " samples under " +
                                   root.string() + " has an object pixel at " + std::to_string(header.image_size) +
                                   " x " + std::to_string(header.image_size) + " px: nothing to score");
  return result;
}

}  // namespace matlearn
