#pragma once
// The two dataset layouts and the split files of the MatPredict benchmark.
//
// The repository's (docs/matpredict_repository.md, sections 1, 2 and 5):
// <root>/<object>/<variant>/{images,albedo,ORM,label,normal_obj}/<stem>.png, pixel-aligned maps
// per frame; sample ids "<object>/<variant>/<stem>".
//
// The paper's texture targets (its section "Training protocol"; docs/matpredict_repository.md,
// section 7): screenshots <root>/rendered_cropped/<object>/<material>/<stem>.png and one
// reference map per material,
// <root>/ground_truth_basecolour/<material>.png and ground_truth_roughness/<material>.png
// (optionally ground_truth_metallic/ and ground_truth_normal/), not aligned with the pixels;
// sample ids "<object>/<material>/<stem>".
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace matdataset {

enum class DatasetLayout { repository, paper_textures };

// paper_textures when root holds rendered_cropped/, else repository.
DatasetLayout dataset_layout(const std::filesystem::path& root);

struct SampleId {
  std::string object, variant, stem;

  std::string str() const { return object + "/" + variant + "/" + stem; }
  // From "<object>/<variant>/<stem>"; throws std::invalid_argument otherwise.
  static SampleId parse(const std::string& id);
  bool operator==(const SampleId& o) const { return object == o.object && variant == o.variant && stem == o.stem; }
};

// Every sample under `root` in the repository loader's order: object and variant folders sorted
// by name, folders whose name starts with "_tmp" skipped, a variant being a folder that holds
// images/, each PNG in it a frame (stems sorted). In the paper's layout, likewise under
// rendered_cropped/, each screenshot a sample. Throws DatasetError (matdataset/format/dataset_error.h)
// naming root when it is not a directory, and naming the files when a frame lacks its albedo or
// ORM (a material its two reference maps), or some frames have a label map and others not
// (require_sample_files in matdataset/format/sample_reader.h): where the repository's loader silently
// trains on fewer frames, the dataset is refused.
std::vector<SampleId> index_dataset(const std::filesystem::path& root);

// A split file as the repository's generate_splits.py writes it (keys name, strategy, seed,
// ratios, counts, train, val, test).
struct SplitFile {
  std::string name, strategy;
  int64_t seed = 0;
  std::vector<std::string> train, val, test;
  std::filesystem::path path;  // the file it was read from, for messages; empty when made here
};

// Throws DatasetError naming the file and the problem: unreadable, not YAML, a list missing or
// not a list of sample ids, or a sample listed twice (in one list or in two: a frame counted
// twice, or one trained on and scored).
SplitFile read_split_file(const std::filesystem::path& path);

// The samples of `split` ("train", "val" or "test") in file order, each checked against the
// files under root: a DatasetError names root when it is not a directory, and the files listed
// samples lack (require_sample_files with the default settings).
std::vector<SampleId> split_samples(const SplitFile& file, const std::string& split, const std::filesystem::path& root);

}  // namespace matdataset
