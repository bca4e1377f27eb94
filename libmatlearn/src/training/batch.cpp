#include "matlearn/training/batch.h"

#include <stdexcept>

namespace matlearn {

torch::Tensor to_chw(const matbase::FloatImage& image) {
  return torch::from_blob(const_cast<float*>(image.values.data()), {image.height, image.width, image.channels},
                          torch::kFloat32)
      .permute({2, 0, 1})
      .clone();
}

matbase::FloatImage to_hwc(const torch::Tensor& chw) {
  const torch::Tensor hwc = chw.permute({1, 2, 0}).contiguous().to(torch::kFloat32);
  matbase::FloatImage image(static_cast<int>(hwc.size(1)), static_cast<int>(hwc.size(0)), static_cast<int>(hwc.size(2)));
  std::copy(hwc.data_ptr<float>(), hwc.data_ptr<float>() + hwc.numel(), image.values.begin());
  return image;
}

torch::Tensor normalize_input(const torch::Tensor& rgb, InputNormalization normalization) {
  if (normalization == InputNormalization::none) return rgb;
  // torchvision's ImageNet statistics, with which every pretrained trunk was trained.
  const torch::Tensor mean = torch::tensor({0.485f, 0.456f, 0.406f}).view({1, 3, 1, 1});
  const torch::Tensor std = torch::tensor({0.229f, 0.224f, 0.225f}).view({1, 3, 1, 1});
  return (rgb - mean) / std;
}

namespace {

const matbase::FloatImage& stored_map(const matdataset::MaterialSample& sample, MapKind map) {
  switch (map) {
    case MapKind::base_color: return sample.albedo;
    case MapKind::roughness: return sample.roughness;
    case MapKind::metallic: return sample.metallic;
    case MapKind::normal: return sample.normal;
  }
  throw std::logic_error("unknown map kind");
}

}  // namespace

matdataset::SampleSettings sample_settings(const OutputLayout& layout, int image_size, bool linear_albedo) {
  matdataset::SampleSettings settings;
  settings.size = image_size;
  settings.linear_albedo = linear_albedo;
  settings.read_normal = layout.predicts(MapKind::normal);
  settings.read_metallic = layout.predicts(MapKind::metallic);
  settings.material_classes = layout.material_classes;
  return settings;
}

matbase::FloatImage target_map(const matdataset::MaterialSample& sample, const OutputGroup& group) {
  const matbase::FloatImage& map = stored_map(sample, group.map);
  if (map.values.empty()) throw std::invalid_argument("the sample has no " + map_name(group.map) + " map");
  if (map.channels == group.channels) return map;
  if (map.channels != 1)
    throw std::invalid_argument("the sample's " + map_name(group.map) + " map has " + std::to_string(map.channels) +
                                " channels, not " + std::to_string(group.channels));
  matbase::FloatImage repeated(map.width, map.height, static_cast<int>(group.channels));
  for (size_t p = 0; p < map.pixel_count(); ++p)
    for (int c = 0; c < repeated.channels; ++c) repeated.values[p * static_cast<size_t>(repeated.channels) + static_cast<size_t>(c)] = map.values[p];
  return repeated;
}

Batch make_batch(const std::vector<matdataset::MaterialSample>& samples, const OutputLayout& layout,
                 InputNormalization normalization) {
  if (samples.empty()) throw std::invalid_argument("make_batch: no samples");
  std::vector<torch::Tensor> inputs, targets, masks, labels;
  for (const matdataset::MaterialSample& s : samples) {
    inputs.push_back(to_chw(s.input));
    std::vector<torch::Tensor> maps;
    for (const OutputGroup& group : layout.groups) maps.push_back(to_chw(target_map(s, group)));
    targets.push_back(maps.empty() ? torch::empty({0, s.input.height, s.input.width}) : torch::cat(maps, 0));
    const int64_t h = s.input.height, w = s.input.width;
    masks.push_back(torch::tensor(std::vector<uint8_t>(s.mask.begin(), s.mask.end())).view({1, h, w}).to(torch::kFloat32));
    labels.push_back(s.has_label ? torch::tensor(std::vector<int64_t>(s.material_id.begin(), s.material_id.end())).view({h, w})
                                 : torch::full({h, w}, kIgnoredLabel, torch::kLong));
  }
  Batch batch;
  batch.input = normalize_input(torch::stack(inputs), normalization);
  batch.target = torch::stack(targets);
  batch.mask = torch::stack(masks);
  batch.labels = torch::stack(labels);
  return batch;
}

}  // namespace matlearn
