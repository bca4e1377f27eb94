#pragma once
// The learned denoiser's training pairs: a frame of a dataset rendered at few samples (the input)
// and the same frame rendered at many (the target), both made by make_dataset with
// render.hdr_images (the colour in floats) from one configuration and different render.seed
// values, so that the frames are the same and the noise independent.
#include <filesystem>
#include <string>
#include <vector>

#include <torch/torch.h>

#include "matdataset/format/dataset_index.h"

namespace matlearn {

struct DenoiserPair {
  torch::Tensor input;   // 9 x H x W: denoiser_input() of the noisy frame, at its own auto-exposure
  torch::Tensor target;  // 3 x H x W: the reference's colour through the transfer function at that exposure
};

// The frames of `reference` every dataset of `noisy` has too, in index order. Throws
// matdataset::DatasetError naming the folder when that leaves none.
std::vector<matdataset::SampleId> paired_frames(const std::filesystem::path& reference,
                                                const std::vector<std::filesystem::path>& noisy);

// Frame `id` of the noisy dataset (images_hdr/, albedo/ for the base colour and coverage,
// normal_obj/) against the reference's images_hdr/. Throws matdataset::DatasetError naming the
// file for a map that is missing, unreadable, of another size, or holds a NaN or an infinity.
DenoiserPair read_denoiser_pair(const std::filesystem::path& noisy, const std::filesystem::path& reference,
                                const matdataset::SampleId& id);

}  // namespace matlearn
