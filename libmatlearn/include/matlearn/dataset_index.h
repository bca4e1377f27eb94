#pragma once
// The MatPredict repository's dataset layout (../shared/reference/matpredict_repo.md, sections 1
// and 3.1-3.2): <root>/<object>/<variant>/{images,albedo,ORM,label,...}/<stem>.png, sample ids
// "<object>/<variant>/<stem>", and the split files its benchmark reads.
#include <filesystem>
#include <string>
#include <vector>

namespace matlearn {

struct SampleId {
  std::string object, variant, stem;

  std::string str() const { return object + "/" + variant + "/" + stem; }
  // From "<object>/<variant>/<stem>"; throws std::invalid_argument otherwise.
  static SampleId parse(const std::string& id);
  bool operator==(const SampleId& o) const { return object == o.object && variant == o.variant && stem == o.stem; }
};

// Every sample under `root` in the repository loader's order: object and variant folders sorted
// by name, folders whose name starts with "_tmp" skipped, a variant counted when it holds
// images/, albedo/ and ORM/, and in it a stem when images/<stem>.png, albedo/<stem>.png and
// ORM/<stem>.png all exist (stems sorted). Throws std::runtime_error naming root when it is not
// a directory.
std::vector<SampleId> index_dataset(const std::filesystem::path& root);

// A split file as the repository's generate_splits.py writes it (keys name, strategy, seed,
// ratios, counts, train, val, test).
struct SplitFile {
  std::string name, strategy;
  int seed = 0;
  std::vector<std::string> train, val, test;
};

// Throws std::runtime_error naming the file and the problem (unreadable, not YAML, a list
// missing or not a list of strings).
SplitFile read_split_file(const std::filesystem::path& path);

// The samples of `split` ("train", "val" or "test") in file order, each checked against the
// files under root: a listed id whose image, albedo or ORM file is missing is an error naming it.
std::vector<SampleId> split_samples(const SplitFile& file, const std::string& split, const std::filesystem::path& root);

}  // namespace matlearn
