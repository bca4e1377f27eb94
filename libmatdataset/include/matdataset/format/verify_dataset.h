#pragma once
// make_dataset --verify: checks a dataset folder against the layout (docs/dataset_format.md),
// whoever wrote it: every frame transforms.json lists has the repository's seven maps (and our
// sample count map where the variant has its folder), of the size it states; the label ids are
// classes of the table and among the variant's used_materials, and the object is in at least one
// pixel; the label, ORM's alpha and the depth map's coverage agree on which pixels hold the
// object, where the depth is finite, positive and within the object's bounding sphere; every
// pixel took between 1 and the stated samples; the segmentation maps are the class table; the
// four split files are there, each listing every frame once and stating the counts of its lists;
// the records parse. It reads every file, so a damaged one is found.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace matdataset {

struct VerifyReport {
  size_t variants = 0;
  size_t frames = 0;
  std::vector<std::string> problems;  // each naming the file
};

// Throws matbase::InputError when `root` is no folder or holds no variant folder at all.
VerifyReport verify_dataset(const std::filesystem::path& root);

}  // namespace matdataset
