#include "matdataset/maker/dataset_plan.h"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

#include "matbase/file/atomic_file.h"
#include "matbase/number_text.h"
#include "matdataset/format/dataset_folders.h"
#include "matdataset/format/dataset_splits.h"
#include "matdataset/format/dataset_writer.h"
#include "matdataset/maker/frame_lighting.h"
#include "matdataset/maker/object_framing.h"
#include "matdataset/maker/seed_stream.h"

namespace matdataset {
namespace {

namespace fs = std::filesystem;

// 390 times the paper's 129,024: beyond it the plan's lists alone would take gigabytes.
constexpr int64_t kMaxFrames = 50'000'000;

std::vector<SlotCandidates> slot_candidates(const ObjectConfig& object) {
  std::vector<SlotCandidates> slots;
  for (const SlotConfig& slot : object.slots) {
    SlotCandidates candidates{slot.key, {}};
    for (const MaterialCandidate& c : slot.candidates) candidates.materials.push_back(c.name);
    slots.push_back(std::move(candidates));
  }
  return slots;
}

}  // namespace

std::optional<Shard> parse_shard(const std::string& text) {
  const size_t slash = text.find('/');
  if (slash == std::string::npos) return std::nullopt;
  const auto index = matbase::whole_number(text.substr(0, slash));
  const auto count = matbase::whole_number(text.substr(slash + 1));
  if (!index || !count || *count < 1 || *count > 1000000 || *index < 0 || *index >= *count) return std::nullopt;
  return Shard{static_cast<int>(*index), static_cast<int>(*count)};
}

DatasetPlan plan_dataset(const DatasetConfig& config) {
  DatasetPlan plan;
  plan.grid_views = static_cast<size_t>(config.camera.n_phi) * static_cast<size_t>(config.camera.n_theta);
  plan.views = plan.grid_views * config.lighting.rounds();
  for (size_t o = 0; o < config.objects.size(); ++o) {
    plan.grid_views_under_floor.push_back(grid_views_under_floor(config, o));
    const std::vector<size_t>& under = plan.grid_views_under_floor.back();
    std::vector<size_t>& views = plan.object_views.emplace_back();
    for (size_t view = 0; view < plan.views; ++view)
      if (!std::binary_search(under.begin(), under.end(), view % plan.grid_views)) views.push_back(view);
  }
  // Counted before anything is listed: an uncapped product of many slots would not fit in memory.
  long double frames = 0;
  for (size_t o = 0; o < config.objects.size(); ++o) {
    uint64_t variants = 0;
    try {
      variants = variant_count(slot_candidates(config.objects[o]), config.combination);
    } catch (const std::invalid_argument& e) {
      throw matbase::InputError(config.source + ": objects." + std::to_string(o) + ": " + e.what());
    }
    if (config.max_variants) variants = std::min(variants, *config.max_variants);
    frames += static_cast<long double>(variants) * static_cast<long double>(config.objects[o].uv_scales.size()) *
              static_cast<long double>(plan.object_views[o].size());
  }
  if (frames > static_cast<long double>(kMaxFrames))
    throw matbase::InputError(fmt::format("{}: the plan has {:.4g} frames, more than the {} one dataset may have; cap the "
                                 "variants (variants.max_variants) or the views (camera.grid)",
                                 config.source, static_cast<double>(frames), matbase::with_thousands(kMaxFrames)));
  for (size_t o = 0; o < config.objects.size(); ++o) {
    try {
      plan.variants.push_back(material_variants(slot_candidates(config.objects[o]), config.combination,
                                              config.max_variants, config.variant_seed));
    } catch (const std::invalid_argument& e) {
      throw matbase::InputError(config.source + ": objects." + std::to_string(o) + ": " + e.what());
    }
    // Several UV scales: every material variant once per scale, the scales varying fastest.
    const size_t scales = config.objects[o].uv_scales.size();
    if (scales > 1) {
      std::vector<MaterialVariant> scaled;
      for (const MaterialVariant& variant : plan.variants.back())
        for (size_t k = 0; k < scales; ++k) {
          scaled.push_back(variant);
          scaled.back().push_back(k);
        }
      plan.variants.back() = std::move(scaled);
    }
    for (size_t v = 0; v < plan.variants.back().size(); ++v)
      for (const size_t view : plan.object_views[o]) plan.frames.push_back({o, v, view});
  }
  return plan;
}

fs::path variant_folder(const DatasetConfig& config, const DatasetPlan& plan, size_t object, size_t variant) {
  return fs::path(config.output) / config.objects[object].name /
         variant_folder_name(variant, plan.variants[object].size());
}

std::string view_stem(const DatasetPlan& plan, size_t view) { return frame_stem(view, plan.views); }

uint32_t frame_seed(uint64_t seed, const FrameRef& frame, uint32_t sample_seed) {
  uint64_t h = splitmix64(seed);
  for (const size_t index : {frame.object, frame.variant, frame.view}) h = splitmix64(h ^ static_cast<uint64_t>(index));
  if (sample_seed != 0) h = splitmix64(h ^ sample_seed);
  return static_cast<uint32_t>(h >> 32);
}

std::vector<std::string> variant_material_names(const ObjectConfig& object, const MaterialVariant& variant) {
  std::vector<std::string> names;
  for (size_t s = 0; s < object.slots.size(); ++s) names.push_back(object.slots[s].candidates[variant[s]].name);
  return names;
}

std::vector<SplitFile> write_dataset_records(const DatasetConfig& config, const DatasetPlan& plan) {
  const fs::path root(config.output);
  fs::create_directories(root / kConfigFolder);
  matbase::remove_stale_temporaries(root / kSegmentationMapFile, false);
  for (const char* split : kSplitFiles) matbase::remove_stale_temporaries(root / kConfigFolder / split, false);
  matbase::remove_stale_temporaries(root / kConfigFolder / kLightingSplitFile, false);
  write_segmentation_map_yaml(root);
  std::vector<SampleId> samples;
  std::vector<std::vector<std::string>> materials;
  std::vector<std::string> lightings;
  for (const FrameRef& frame : plan.frames) {
    lightings.push_back(
        lighting_key(config.lighting, choose_lighting(config.lighting, config.seed, frame, plan.grid_views)));
    samples.push_back({config.objects[frame.object].name,
                       variant_folder_name(frame.variant, plan.variants[frame.object].size()),
                       view_stem(plan, frame.view)});
    materials.push_back(variant_material_names(config.objects[frame.object], plan.variants[frame.object][frame.variant]));
  }
  // The repository's loader sorts objects, variants and stems: so do the splits' inputs.
  std::vector<size_t> order(samples.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return samples[a].str() < samples[b].str(); });
  std::vector<SampleId> sorted;
  std::vector<std::vector<std::string>> sorted_materials;
  std::vector<std::string> sorted_lightings;
  for (const size_t k : order)
    sorted.push_back(samples[k]), sorted_materials.push_back(materials[k]), sorted_lightings.push_back(lightings[k]);

  const std::string dataset_root = "..";  // the split files' folder's parent: relative, so any copy reads the same
  const SplitRatios& ratios = config.split_ratios;
  const double train = config.paper_train_fraction;
  const std::vector<std::pair<SplitFile, SplitRatios>> splits = {
      {object_disjoint_split(sorted, ratios, config.split_seed), ratios},
      {variant_disjoint_split(sorted, ratios, config.split_seed), ratios},
      {material_disjoint_split(sorted, sorted_materials, ratios, config.split_seed), ratios},
      {random_split(sorted, train, config.split_seed), {train, 0.0, 1.0 - train}},
      {lighting_disjoint_split(sorted, sorted_lightings, ratios, config.split_seed), ratios}};
  std::vector<SplitFile> written;
  for (const auto& [split, split_ratios] : splits) {
    write_split_file(root / kConfigFolder / (split.name + ".yaml"), split, split_ratios, dataset_root);
    written.push_back(split);
  }
  return written;
}

}  // namespace matdataset
