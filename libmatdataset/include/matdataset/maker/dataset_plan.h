#pragma once
// What a configuration asks to render: each object's material variants and views, every frame
// (object, variant, view) in one fixed order, the shard each frame belongs to, each frame's seed
// and sample id, and the split files, which all follow from the configuration (and, for an object
// on a floor seen from below the horizon, its mesh), so every shard of a run writes the same ones.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "matdataset/format/dataset_index.h"
#include "matdataset/maker/dataset_config.h"
#include "matdataset/maker/material_variants.h"

namespace matdataset {

// Shard `index` of `count`: frames k with k mod count == index.
struct Shard {
  int index = 0;
  int count = 1;
  bool owns(size_t frame) const { return frame % static_cast<size_t>(count) == static_cast<size_t>(index); }
};
// "K/N" with 0 <= K < N; nothing when the text is not that.
std::optional<Shard> parse_shard(const std::string& text);

struct FrameRef {
  size_t object = 0;
  size_t variant = 0;  // among the object's variants
  // The grid's index i * n_theta + j, plus the grid's size times the setup's index when every
  // lighting setup renders every view (LightingAssignment::EverySetup).
  size_t view = 0;
};

struct DatasetPlan {
  // Per object, its variants: for each slot in order, the index of its candidate.
  std::vector<std::vector<MaterialVariant>> variants;
  size_t grid_views = 0;  // n_phi x n_theta
  size_t views = 0;       // the grid's views times the lighting's rounds
  // Per object, the views it renders, ascending: all of them but those whose camera is under the
  // floor it stands on (grid_views_under_floor), in every lighting round.
  std::vector<std::vector<size_t>> object_views;
  // Per object, the grid views left out so.
  std::vector<std::vector<size_t>> grid_views_under_floor;
  std::vector<FrameRef> frames;  // object by object, variant by variant, view by view
};

// Throws matbase::InputError when an object's variants cannot be formed (a cartesian product too
// large) or an object on a floor seen from below cannot be read.
DatasetPlan plan_dataset(const DatasetConfig& config);

// The folder of a variant and a frame's stem.
std::filesystem::path variant_folder(const DatasetConfig& config, const DatasetPlan& plan, size_t object,
                                     size_t variant);
std::string view_stem(const DatasetPlan& plan, size_t view);

// The seed of a frame's samples: a hash of the configuration's seed and the frame's indices (and
// of render.seed, `sample_seed`, where it is not 0), so a frame renders the same in any shard, run
// or resumed run, and another render.seed renders the same frames (objects, materials, lighting,
// every draw) with independent noise.
uint32_t frame_seed(uint64_t seed, const FrameRef& frame, uint32_t sample_seed = 0);

// The names of the candidate materials of a variant, slot by slot.
std::vector<std::string> variant_material_names(const ObjectConfig& object, const MaterialVariant& variant);

// Writes material_segmentation_map.yaml and config/ with the split files (the repository's
// object_disjoint_v1 and variance_disjoint_v1, material_disjoint_v1, paper_random_v1) of every
// frame of the plan, and returns them.
std::vector<SplitFile> write_dataset_records(const DatasetConfig& config, const DatasetPlan& plan);

}  // namespace matdataset
