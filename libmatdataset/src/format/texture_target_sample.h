#pragma once
// One sample of the paper's texture-target layout (matdataset/format/dataset_index.h): the screenshot
// resized as the repository's inputs are, and its material's reference maps resized whole to the
// same size. These are the paper's targets; they are not aligned with the pixels, so every pixel
// counts in the loss and there is no label.
#include <filesystem>
#include <vector>

#include "matdataset/format/dataset_index.h"
#include "matdataset/format/sample_reader.h"

namespace matdataset {

// Reference maps are decoded and resized once per process and size, then shared by every
// sample of the material (the paper's loader keeps them in memory too). ground_truth_metallic/
// is read when present (it must be with settings.read_metallic), ground_truth_normal/ when
// settings.read_normal asks for it. Throws DatasetError naming the file when a map cannot be read
// or holds a NaN or an infinity.
MaterialSample read_texture_target_sample(const std::filesystem::path& root, const SampleId& id,
                                          const SampleSettings& settings);

// The files read_texture_target_sample needs for `id` with `settings`.
std::vector<std::filesystem::path> texture_target_files(const std::filesystem::path& root, const SampleId& id,
                                                        const SampleSettings& settings);

}  // namespace matdataset
