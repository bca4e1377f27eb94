#pragma once
// Batches of dataset samples (matdataset/format/sample_reader.h) decoded on worker threads, in an order
// fixed by the seed and the epoch alone: the same batches whatever the thread count.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "matdataset/format/dataset_index.h"
#include "matdataset/format/sample_reader.h"

namespace matdataset {

struct LoaderSettings {
  SampleSettings sample;
  int batch_size = 8;
  bool shuffle = true;   // a new permutation every epoch
  uint64_t seed = 42;    // the paper's
  int threads = 0;       // decoding threads; 0 = all hardware threads
  bool drop_last = false;
};

class SampleLoader {
 public:
  SampleLoader(std::filesystem::path root, std::vector<SampleId> samples, LoaderSettings settings);

  size_t sample_count() const { return samples_.size(); }
  size_t batch_count() const;
  // Indices into the samples in the order epoch `epoch` visits them.
  std::vector<size_t> epoch_order(int epoch) const;
  // Batch `batch` of epoch `epoch`, its samples decoded in parallel.
  std::vector<MaterialSample> batch(int epoch, size_t batch) const;
  const std::vector<SampleId>& samples() const { return samples_; }

 private:
  std::filesystem::path root_;
  std::vector<SampleId> samples_;
  LoaderSettings settings_;
};

// A permutation of 0 .. n-1 from the seed: Fisher-Yates driven by SplitMix64 (Steele, Lea,
// Flood 2014), both specified here so the order does not depend on the standard library.
std::vector<size_t> seeded_permutation(size_t n, uint64_t seed);

struct SplitRatios {
  double train = 0.8, val = 0.2, test = 0.0;  // the paper's 80/20
};

// Without a split file: whole variant folders (all views of one material assignment) go to one
// split, so no view of a test variant is seen in training. The folders are shuffled with the
// seed; val and test get floor(ratio * folders), train the rest. Returns train, val, test.
std::vector<std::vector<SampleId>> split_by_variant(const std::vector<SampleId>& samples, const SplitRatios& ratios,
                                                    uint64_t seed);

}  // namespace matdataset
