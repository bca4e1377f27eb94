#include "matlearn/denoising/denoiser_pairs.h"

#include <algorithm>
#include <set>

#include "matbase/image/srgb.h"
#include "matdataset/format/dataset_error.h"
#include "matdataset/format/decoded_image.h"
#include "matlearn/denoising/denoiser_input.h"
#include "matlearn/denoising/hdr_transfer.h"

namespace matlearn {
namespace {

namespace fs = std::filesystem;

fs::path map_file(const fs::path& root, const matdataset::SampleId& id, const char* folder, const char* extension) {
  return root / id.object / id.variant / folder / (id.stem + extension);
}

// A map of `channels` channels at the noisy image's size.
matbase::FloatImage read_map(const fs::path& file, int width, int height, int channels) {
  matbase::FloatImage map = matdataset::decode_finite(file);
  if (width > 0) matdataset::check_same_size(width, height, map, file);
  matdataset::check_channels(map, channels, "RGBA", file);
  return map;
}

// The first three of `channels` interleaved channels per pixel.
std::vector<float> rgb_of(const matbase::FloatImage& image) {
  const size_t n = static_cast<size_t>(image.width) * static_cast<size_t>(image.height);
  std::vector<float> rgb(3 * n);
  for (size_t p = 0; p < n; ++p)
    for (size_t c = 0; c < 3; ++c) rgb[3 * p + c] = image.values[static_cast<size_t>(image.channels) * p + c];
  return rgb;
}

}  // namespace

std::vector<matdataset::SampleId> paired_frames(const fs::path& reference, const std::vector<fs::path>& noisy) {
  std::vector<matdataset::SampleId> frames;
  std::vector<std::set<std::string>> noisy_frames;
  for (const fs::path& dataset : noisy) {
    std::set<std::string> ids;
    for (const matdataset::SampleId& id : matdataset::index_dataset(dataset)) ids.insert(id.str());
    noisy_frames.push_back(std::move(ids));
  }
  for (const matdataset::SampleId& id : matdataset::index_dataset(reference))
    if (std::all_of(noisy_frames.begin(), noisy_frames.end(), [&id](const auto& ids) { return ids.count(id.str()) > 0; }))
      frames.push_back(id);
  if (frames.empty())
    throw matdataset::DatasetError(reference.string() + ": no frame of it is in every noisy dataset");
  return frames;
}

DenoiserPair read_denoiser_pair(const fs::path& noisy, const fs::path& reference, const matdataset::SampleId& id) {
  const matbase::FloatImage hdr = read_map(map_file(noisy, id, "images_hdr", ".exr"), 0, 0, 4);
  const int w = hdr.width, h = hdr.height;
  const matbase::FloatImage albedo_map = read_map(map_file(noisy, id, "albedo", ".png"), w, h, 4);
  const matbase::FloatImage normal_map = read_map(map_file(noisy, id, "normal_obj", ".png"), w, h, 4);
  const matbase::FloatImage target_map = read_map(map_file(reference, id, "images_hdr", ".exr"), w, h, 4);
  const size_t n = static_cast<size_t>(w) * static_cast<size_t>(h);
  // The maps as the renderer's AOVs hold them: the albedo PNG is sRGB with straight alpha (the
  // coverage), the normal PNG 0.5 n + 0.5 where a surface is.
  std::vector<float> albedo(3 * n), normal(3 * n, 0.0f), coverage(n);
  for (size_t p = 0; p < n; ++p) {
    coverage[p] = albedo_map.values[4 * p + 3];
    for (size_t c = 0; c < 3; ++c) {
      albedo[3 * p + c] = matbase::srgb_to_linear(albedo_map.values[4 * p + c]);
      if (normal_map.values[4 * p + 3] > 0.0f) normal[3 * p + c] = 2.0f * normal_map.values[4 * p + c] - 1.0f;
    }
  }
  const std::vector<float> color = rgb_of(hdr), target = rgb_of(target_map);
  const float exposure = auto_exposure(color.data(), w, h);
  DenoiserPair pair;
  pair.input = denoiser_input({w, h, color.data(), albedo.data(), normal.data(), coverage.data()}, exposure)[0];
  const torch::Tensor target_rgb =
      torch::from_blob(const_cast<float*>(target.data()), {h, w, 3}, torch::kFloat32).permute({2, 0, 1});
  pair.target = hdr_transfer(target_rgb * exposure).contiguous();
  return pair;
}

}  // namespace matlearn
