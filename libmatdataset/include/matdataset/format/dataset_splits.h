#pragma once
// The split files of a dataset (docs/dataset_format.md, "Splits"): the repository's two
// strategies with its algorithm, ratios and seed, so that the same samples give the same split
// files as its generate_splits.py, a material-disjoint split it lacks, and the paper's seeded
// random 80/20 split. Each is a SplitFile (matdataset/format/dataset_index.h) that read_split_file and the
// repository's loader read.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "matdataset/format/dataset_index.h"

namespace matdataset {

struct SplitRatios {
  double train = 0.7, val = 0.15, test = 0.15;
};

// The repository's balanced assignment: the groups (in the order their key first appears among
// `samples`) shuffled with Python's random.Random(seed), stably sorted by size, largest first,
// and each given to the split furthest below its target (ratio x total; ties to the split with
// fewer samples, then train, val, test); each split's ids sorted. group_of[k] is the group key
// of samples[k]. Throws std::invalid_argument when the two lists differ in length or the ratios
// are negative or do not sum to 1.
SplitFile balanced_group_split(const std::vector<SampleId>& samples, const std::vector<std::string>& group_of,
                               const SplitRatios& ratios, uint64_t seed);

// The repository's object_disjoint (grouped by object) and variance_disjoint (grouped by the
// variant folder's name across objects, its "var012": not material-disjoint, its W15) splits.
SplitFile object_disjoint_split(const std::vector<SampleId>& samples, const SplitRatios& ratios, uint64_t seed);
SplitFile variant_disjoint_split(const std::vector<SampleId>& samples, const SplitRatios& ratios, uint64_t seed);

// No material in two splits: variants that share a material (directly or through others) form
// one group, and the groups are split as above. materials_of[k] lists the materials of
// samples[k]'s variant. With many slots whose candidates overlap, the groups can merge into few.
SplitFile material_disjoint_split(const std::vector<SampleId>& samples,
                                  const std::vector<std::vector<std::string>>& materials_of,
                                  const SplitRatios& ratios, uint64_t seed);

// No lighting in two splits (Kubric's rule for its HDRIs: test frames are lit by what no training
// frame is): samples grouped by lighting_of[k], samples[k]'s lighting key (its environment image,
// else its setup), and the groups split as above.
SplitFile lighting_disjoint_split(const std::vector<SampleId>& samples, const std::vector<std::string>& lighting_of,
                                  const SplitRatios& ratios, uint64_t seed);
// The paper's split: the samples shuffled with random.Random(seed), the first
// floor(train_fraction x count) for training and the rest for testing (val is empty).
SplitFile random_split(const std::vector<SampleId>& samples, double train_fraction, uint64_t seed);

// Writes the split as generate_splits.py does (name, strategy, seed, ratios, dataset_root,
// counts, train, val, test), dataset_root being `dataset_root` as given.
void write_split_file(const std::filesystem::path& path, const SplitFile& split, const SplitRatios& ratios,
                      const std::string& dataset_root);

}  // namespace matdataset
