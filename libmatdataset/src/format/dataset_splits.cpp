#include "matdataset/format/dataset_splits.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>

#include <yaml-cpp/yaml.h>

#include "matbase/file/atomic_file.h"
#include "matdataset/format/python_random.h"

namespace matdataset {
namespace {

struct Group {
  std::string key;
  std::vector<std::string> ids;
};

void check_ratios(const SplitRatios& r) {
  if (!(r.train >= 0.0 && r.val >= 0.0 && r.test >= 0.0) || std::abs(r.train + r.val + r.test - 1.0) > 1e-6)
    throw std::invalid_argument("split ratios must be non-negative and sum to 1");
}

std::vector<std::string>& split_list(SplitFile& file, size_t split) {
  return split == 0 ? file.train : split == 1 ? file.val : file.test;
}

void sort_lists(SplitFile& file) {
  for (size_t s = 0; s < 3; ++s) std::sort(split_list(file, s).begin(), split_list(file, s).end());
}

// Union-find over material names.
class MaterialComponents {
 public:
  size_t find(const std::string& material) {
    const auto [it, added] = index_.emplace(material, parent_.size());
    if (added) parent_.push_back(it->second);
    size_t k = it->second;
    while (parent_[k] != k) k = parent_[k] = parent_[parent_[k]];
    return k;
  }
  void unite(const std::string& a, const std::string& b) {
    const size_t ra = find(a), rb = find(b);
    parent_[std::max(ra, rb)] = std::min(ra, rb);
  }

 private:
  std::map<std::string, size_t> index_;
  std::vector<size_t> parent_;
};

}  // namespace

SplitFile balanced_group_split(const std::vector<SampleId>& samples, const std::vector<std::string>& group_of,
                               const SplitRatios& ratios, uint64_t seed) {
  if (samples.size() != group_of.size()) throw std::invalid_argument("balanced split: one group key per sample");
  check_ratios(ratios);
  std::vector<Group> groups;
  std::map<std::string, size_t> group_index;
  for (size_t k = 0; k < samples.size(); ++k) {
    const auto [it, added] = group_index.emplace(group_of[k], groups.size());
    if (added) groups.push_back({group_of[k], {}});
    groups[it->second].ids.push_back(samples[k].str());
  }
  PythonRandom random(seed);
  random.shuffle(groups);
  std::stable_sort(groups.begin(), groups.end(),
                   [](const Group& a, const Group& b) { return a.ids.size() > b.ids.size(); });

  const double total = static_cast<double>(samples.size());
  const std::array<double, 3> targets = {total * ratios.train, total * ratios.val, total * ratios.test};
  std::array<size_t, 3> counts = {0, 0, 0};
  SplitFile file;
  file.seed = static_cast<int64_t>(seed);
  for (const Group& group : groups) {
    // The largest (remaining target, -count), the first split on a tie: Python's tuple order.
    size_t best = 0;
    for (size_t s = 1; s < 3; ++s) {
      const double remaining = targets[s] - static_cast<double>(counts[s]);
      const double best_remaining = targets[best] - static_cast<double>(counts[best]);
      if (remaining > best_remaining || (remaining == best_remaining && counts[s] < counts[best])) best = s;
    }
    std::vector<std::string>& list = split_list(file, best);
    list.insert(list.end(), group.ids.begin(), group.ids.end());
    counts[best] += group.ids.size();
  }
  sort_lists(file);
  return file;
}

namespace {

// The balanced split of the samples grouped by key_of, named as the repository names its files.
template <typename Key>
SplitFile keyed_split(const std::vector<SampleId>& samples, Key key_of, const char* name, const char* strategy,
                      const SplitRatios& ratios, uint64_t seed) {
  std::vector<std::string> keys;
  for (const SampleId& id : samples) keys.push_back(key_of(id));
  SplitFile file = balanced_group_split(samples, keys, ratios, seed);
  file.name = name;
  file.strategy = strategy;
  return file;
}

}  // namespace

SplitFile object_disjoint_split(const std::vector<SampleId>& samples, const SplitRatios& ratios, uint64_t seed) {
  return keyed_split(samples, [](const SampleId& id) { return id.object; }, "object_disjoint_v1", "object_disjoint",
                     ratios, seed);
}

// "variance_disjoint": the repository's spelling, which its tools check.
SplitFile variant_disjoint_split(const std::vector<SampleId>& samples, const SplitRatios& ratios, uint64_t seed) {
  return keyed_split(samples, [](const SampleId& id) { return id.variant; }, "variance_disjoint_v1",
                     "variance_disjoint", ratios, seed);
}

SplitFile material_disjoint_split(const std::vector<SampleId>& samples,
                                  const std::vector<std::vector<std::string>>& materials_of, const SplitRatios& ratios,
                                  uint64_t seed) {
  if (samples.size() != materials_of.size()) throw std::invalid_argument("material split: one material list per sample");
  MaterialComponents components;
  for (const std::vector<std::string>& materials : materials_of) {
    if (materials.empty()) throw std::invalid_argument("material split: a sample has no material");
    for (const std::string& material : materials) components.unite(materials.front(), material);
  }
  // A group is named by the first material (in sample order) of its component.
  std::map<size_t, std::string> component_names;
  std::vector<std::string> keys;
  for (const std::vector<std::string>& materials : materials_of) {
    const auto [it, added] = component_names.emplace(components.find(materials.front()), materials.front());
    keys.push_back(it->second);
  }
  SplitFile file = balanced_group_split(samples, keys, ratios, seed);
  file.name = "material_disjoint_v1";
  file.strategy = "material_disjoint";
  return file;
}

SplitFile lighting_disjoint_split(const std::vector<SampleId>& samples, const std::vector<std::string>& lighting_of,
                                  const SplitRatios& ratios, uint64_t seed) {
  if (samples.size() != lighting_of.size()) throw std::invalid_argument("lighting split: one lighting key per sample");
  SplitFile file = balanced_group_split(samples, lighting_of, ratios, seed);
  file.name = "lighting_disjoint_v1";
  file.strategy = "lighting_disjoint";
  return file;
}

SplitFile random_split(const std::vector<SampleId>& samples, double train_fraction, uint64_t seed) {
  if (!(train_fraction >= 0.0 && train_fraction <= 1.0))
    throw std::invalid_argument("random split: the training fraction must be in [0, 1]");
  std::vector<std::string> ids;
  for (const SampleId& id : samples) ids.push_back(id.str());
  PythonRandom random(seed);
  random.shuffle(ids);
  const auto train = static_cast<size_t>(std::floor(train_fraction * static_cast<double>(ids.size())));
  SplitFile file;
  file.name = "paper_random_v1";
  file.strategy = "random";
  file.seed = static_cast<int64_t>(seed);
  file.train.assign(ids.begin(), ids.begin() + static_cast<std::ptrdiff_t>(train));
  file.test.assign(ids.begin() + static_cast<std::ptrdiff_t>(train), ids.end());
  sort_lists(file);
  return file;
}

void write_split_file(const std::filesystem::path& path, const SplitFile& split, const SplitRatios& ratios,
                      const std::string& dataset_root) {
  YAML::Emitter out;
  out.SetDoublePrecision(15);  // 0.7, not 0.69999999999999996: what a person and Python write
  out << YAML::BeginMap;
  out << YAML::Key << "name" << YAML::Value << split.name;
  out << YAML::Key << "strategy" << YAML::Value << split.strategy;
  out << YAML::Key << "seed" << YAML::Value << split.seed;
  out << YAML::Key << "ratios" << YAML::Value << YAML::BeginMap << YAML::Key << "train" << YAML::Value << ratios.train
      << YAML::Key << "val" << YAML::Value << ratios.val << YAML::Key << "test" << YAML::Value << ratios.test
      << YAML::EndMap;
  out << YAML::Key << "dataset_root" << YAML::Value << dataset_root;
  const size_t total = split.train.size() + split.val.size() + split.test.size();
  out << YAML::Key << "counts" << YAML::Value << YAML::BeginMap << YAML::Key << "train" << YAML::Value
      << split.train.size() << YAML::Key << "val" << YAML::Value << split.val.size() << YAML::Key << "test"
      << YAML::Value << split.test.size() << YAML::Key << "total" << YAML::Value << total << YAML::EndMap;
  for (const auto& [key, list] : {std::pair{"train", &split.train}, {"val", &split.val}, {"test", &split.test}}) {
    out << YAML::Key << key << YAML::Value;
    if (list->empty()) out << YAML::Flow;
    out << YAML::BeginSeq;
    for (const std::string& id : *list) out << id;
    out << YAML::EndSeq;
  }
  out << YAML::EndMap;
  if (!out.good()) throw std::runtime_error(path.string() + ": cannot write the split: " + out.GetLastError());
  matbase::write_file_atomically(path, std::string(out.c_str()) + "\n");
}

}  // namespace matdataset
