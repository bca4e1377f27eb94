#include "matdataset/format/sample_loader.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "matbase/threads.h"

namespace matdataset {
namespace {

uint64_t splitmix64(uint64_t& state) {
  uint64_t z = (state += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

// Uniform in [0, bound): reject the lowest 2^64 mod bound values, which would favour the small
// results, then reduce (OpenBSD's arc4random_uniform).
uint64_t uniform_below(uint64_t bound, uint64_t& state) {
  const uint64_t threshold = (0 - bound) % bound;
  while (true) {
    const uint64_t x = splitmix64(state);
    if (x >= threshold) return x % bound;
  }
}

}  // namespace

std::vector<size_t> seeded_permutation(size_t n, uint64_t seed) {
  std::vector<size_t> order(n);
  for (size_t i = 0; i < n; ++i) order[i] = i;
  uint64_t state = seed;
  for (size_t i = n; i > 1; --i) std::swap(order[i - 1], order[uniform_below(i, state)]);
  return order;
}

SampleLoader::SampleLoader(std::filesystem::path root, std::vector<SampleId> samples, LoaderSettings settings)
    : root_(std::move(root)), samples_(std::move(samples)), settings_(settings) {
  if (settings_.batch_size < 1) throw std::invalid_argument("SampleLoader: batch size must be at least 1");
  if (settings_.threads < 0) throw std::invalid_argument("SampleLoader: threads must be >= 0");
}

size_t SampleLoader::batch_count() const {
  const size_t b = static_cast<size_t>(settings_.batch_size);
  return settings_.drop_last ? samples_.size() / b : (samples_.size() + b - 1) / b;
}

std::vector<size_t> SampleLoader::epoch_order(int epoch) const {
  if (!settings_.shuffle) {
    std::vector<size_t> order(samples_.size());
    std::iota(order.begin(), order.end(), size_t{0});
    return order;
  }
  // One stream per epoch: the seed and the epoch number, mixed.
  uint64_t state = settings_.seed ^ (0xd1b54a32d192ed03ull * (static_cast<uint64_t>(epoch) + 1));
  return seeded_permutation(samples_.size(), splitmix64(state));
}

std::vector<MaterialSample> SampleLoader::batch(int epoch, size_t batch) const {
  if (batch >= batch_count())
    throw std::out_of_range("SampleLoader: batch " + std::to_string(batch) + " of " + std::to_string(batch_count()));
  const std::vector<size_t> order = epoch_order(epoch);
  const size_t first = batch * static_cast<size_t>(settings_.batch_size);
  const size_t count = std::min(static_cast<size_t>(settings_.batch_size), order.size() - first);
  std::vector<MaterialSample> out(count);
  tbb::task_arena arena(matbase::worker_threads(settings_.threads));
  arena.execute([&] {
    tbb::parallel_for(size_t{0}, count, [&](size_t i) {
      out[i] = read_sample(root_, samples_[order[first + i]], settings_.sample);
    });
  });
  return out;
}

std::vector<std::vector<SampleId>> split_by_variant(const std::vector<SampleId>& samples, const SplitRatios& ratios,
                                                    uint64_t seed) {
  if (!(ratios.train >= 0.0 && ratios.val >= 0.0 && ratios.test >= 0.0) ||
      std::abs(ratios.train + ratios.val + ratios.test - 1.0) > 1e-9)
    throw std::invalid_argument("split ratios must be non-negative and sum to 1");
  // Variant folders in first-seen (index) order.
  std::vector<std::string> folders;
  std::map<std::string, std::vector<SampleId>> by_folder;
  for (const SampleId& s : samples) {
    const std::string key = s.object + "/" + s.variant;
    if (by_folder.find(key) == by_folder.end()) folders.push_back(key);
    by_folder[key].push_back(s);
  }
  const std::vector<size_t> order = seeded_permutation(folders.size(), seed);
  const size_t n_val = static_cast<size_t>(std::floor(ratios.val * static_cast<double>(folders.size())));
  const size_t n_test = static_cast<size_t>(std::floor(ratios.test * static_cast<double>(folders.size())));
  const size_t n_train = folders.size() - n_val - n_test;
  std::vector<std::vector<SampleId>> splits(3);
  for (size_t i = 0; i < order.size(); ++i) {
    const size_t split = i < n_train ? 0 : (i < n_train + n_val ? 1 : 2);
    const std::vector<SampleId>& folder = by_folder[folders[order[i]]];
    splits[split].insert(splits[split].end(), folder.begin(), folder.end());
  }
  return splits;
}

}  // namespace matdataset
