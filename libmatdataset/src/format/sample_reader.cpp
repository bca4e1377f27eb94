#include "matdataset/format/sample_reader.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "format/texture_target_sample.h"
#include "matbase/image/object_crop.h"
#include "matbase/image/srgb.h"
#include "matdataset/format/dataset_error.h"
#include "matdataset/format/decoded_image.h"
#include "matdataset/format/resample.h"

namespace matdataset {
namespace {

namespace fs = std::filesystem;

// How many missing files an error names; the count says how many more there are.
constexpr size_t kNamedFiles = 3;

// The repository layout's file of the frame in map folder `map`.
fs::path frame_file(const fs::path& root, const SampleId& id, const char* map) {
  return root / id.object / id.variant / map / (id.stem + ".png");
}

// The label's ids at full resolution, each checked against the network's classes.
std::vector<int32_t> label_ids(const fs::path& path, const matbase::FloatImage& image, int64_t material_classes) {
  DecodedIds label = decode_ids(path);
  check_same_size(label.width, label.height, image, path);
  if (material_classes > 0)
    for (size_t p = 0; p < label.ids.size(); ++p)
      if (label.ids[p] >= material_classes)
        throw DatasetError(path.string() + ": pixel (" + std::to_string(p % static_cast<size_t>(label.width)) + ", " +
                           std::to_string(p / static_cast<size_t>(label.width)) + ") holds label id " +
                           std::to_string(label.ids[p]) + ", beyond the network's " + std::to_string(material_classes) +
                           " material classes (ids 0 to " + std::to_string(material_classes - 1) + ")");
  return std::move(label.ids);
}

std::string listed(const std::vector<fs::path>& files) {
  std::string text;
  for (size_t i = 0; i < std::min(files.size(), kNamedFiles); ++i) text += (i ? ", " : "") + files[i].string();
  if (files.size() > kNamedFiles) text += " and " + std::to_string(files.size() - kNamedFiles) + " more";
  return text;
}

// An image and its object mask at size x size, as samples' inputs are resized.
InputImage resized_input(const matbase::FloatImage& rgb, const matbase::Mask& object, int size) {
  const std::vector<int32_t> ids(object.begin(), object.end());
  InputImage input;
  input.rgb = resize_bilinear(rgb, size, size);
  const std::vector<int32_t> resized = resize_nearest(ids, rgb.width, rgb.height, size, size);
  input.mask.assign(resized.begin(), resized.end());
  return input;
}

}  // namespace

std::vector<fs::path> sample_files(const fs::path& root, const SampleId& id, const SampleSettings& settings) {
  if (dataset_layout(root) == DatasetLayout::paper_textures) return texture_target_files(root, id, settings);
  std::vector<fs::path> files = {frame_file(root, id, "images"), frame_file(root, id, "albedo"),
                                 frame_file(root, id, "ORM")};
  if (settings.material_classes > 0) files.push_back(frame_file(root, id, "label"));
  if (settings.read_normal) files.push_back(frame_file(root, id, "normal_obj"));
  return files;
}

void require_sample_files(const fs::path& root, const std::vector<SampleId>& samples, const SampleSettings& settings,
                          const std::string& context) {
  std::vector<fs::path> missing;
  for (const SampleId& id : samples)
    for (const fs::path& file : sample_files(root, id, settings))
      if (!fs::is_regular_file(file)) missing.push_back(file);
  if (!missing.empty())
    throw DatasetError(context + ": " + std::to_string(missing.size()) + " map file" +
                       (missing.size() == 1 ? " is" : "s are") + " missing: " + listed(missing));
  if (dataset_layout(root) == DatasetLayout::paper_textures || settings.material_classes > 0) return;
  std::vector<fs::path> unlabelled;
  for (const SampleId& id : samples)
    if (!fs::is_regular_file(frame_file(root, id, "label"))) unlabelled.push_back(frame_file(root, id, "label"));
  if (!unlabelled.empty() && unlabelled.size() < samples.size())
    throw DatasetError(context + ": " + std::to_string(unlabelled.size()) + " of " + std::to_string(samples.size()) +
                       " frames have no label map, which is the others' object mask (without it every pixel, the "
                       "background too, would count as object): " + listed(unlabelled));
}

MaterialSample read_sample(const fs::path& root, const SampleId& id, const SampleSettings& settings) {
  if (settings.size < 1) throw std::invalid_argument("read_sample: size must be at least 1");
  if (dataset_layout(root) == DatasetLayout::paper_textures) return read_texture_target_sample(root, id, settings);
  const fs::path albedo_path = frame_file(root, id, "albedo"), orm_path = frame_file(root, id, "ORM");
  const matbase::FloatImage image = decode_finite(frame_file(root, id, "images"));
  const matbase::FloatImage albedo = decode_finite(albedo_path);
  const matbase::FloatImage orm = decode_finite(orm_path);
  check_same_size(albedo.width, albedo.height, image, albedo_path);
  check_same_size(orm.width, orm.height, image, orm_path);
  check_channels(orm, 3, "roughness in G and metallic in B", orm_path);

  MaterialSample sample;
  const int s = settings.size;
  // Label ids and the object mask at full resolution; the targets' resize weights. A network
  // with a segmentation head needs the label; without one a missing label makes every pixel the
  // object, as in the repository.
  std::vector<int32_t> ids(static_cast<size_t>(image.width) * static_cast<size_t>(image.height), 1);
  const fs::path label_path = frame_file(root, id, "label");
  sample.has_label = settings.material_classes > 0 || fs::is_regular_file(label_path);
  if (sample.has_label) ids = label_ids(label_path, image, settings.material_classes);
  std::vector<float> weights(ids.size());
  for (size_t p = 0; p < ids.size(); ++p) weights[p] = ids[p] > 0 ? 1.0f : 0.0f;

  sample.input = resize_bilinear(channels_of(image, 0, 3), s, s);
  matbase::FloatImage albedo_rgb = channels_of(albedo, 0, 3);
  if (settings.linear_albedo)
    for (float& v : albedo_rgb.values) v = matbase::srgb_to_linear(v);
  sample.albedo = resize_bilinear_weighted(albedo_rgb, weights, s, s);
  sample.roughness = resize_bilinear_weighted(channels_of(orm, 1, 1), weights, s, s);
  sample.metallic = resize_bilinear_weighted(channels_of(orm, 2, 1), weights, s, s);
  if (settings.read_normal) {
    const fs::path normal_path = frame_file(root, id, "normal_obj");
    const matbase::FloatImage normal = decode_finite(normal_path);
    check_same_size(normal.width, normal.height, image, normal_path);
    check_channels(normal, 3, "the normal's x, y and z", normal_path);
    sample.normal = resize_unit_vectors(channels_of(normal, 0, 3), weights, s, s);
  }
  sample.material_id = resize_nearest(ids, image.width, image.height, s, s);
  sample.mask.resize(sample.material_id.size());
  for (size_t p = 0; p < sample.mask.size(); ++p) sample.mask[p] = sample.material_id[p] > 0;
  return sample;
}

PhotoInput read_photo(const fs::path& image_path, const fs::path& mask_path) {
  const matbase::FloatImage image = decode_finite(image_path);
  PhotoInput photo;
  photo.rgb = channels_of(image, 0, 3);
  const size_t pixels = image.pixel_count();
  if (!mask_path.empty()) {
    const matbase::FloatImage mask = decode_finite(mask_path);
    check_same_size(mask.width, mask.height, image, mask_path);
    photo.mask.emplace(pixels);
    for (size_t p = 0; p < pixels; ++p) (*photo.mask)[p] = mask.values[p * static_cast<size_t>(mask.channels)] > 0.0f;
  } else {
    photo.mask = alpha_mask(image);
  }
  return photo;
}

std::optional<matbase::Mask> alpha_mask(const matbase::FloatImage& image) {
  if (image.channels != 2 && image.channels != 4) return std::nullopt;
  matbase::Mask alpha(image.pixel_count());
  for (size_t p = 0; p < alpha.size(); ++p)
    alpha[p] = image.values[p * static_cast<size_t>(image.channels) + static_cast<size_t>(image.channels - 1)] > 0.0f;
  if (std::find(alpha.begin(), alpha.end(), 0) == alpha.end()) return std::nullopt;
  return alpha;
}

InputImage read_input_image(const fs::path& image_path, const fs::path& mask_path, int size) {
  if (size < 1) throw std::invalid_argument("read_input_image: size must be at least 1");
  PhotoInput photo = read_photo(image_path, mask_path);
  const matbase::Mask object = photo.mask ? std::move(*photo.mask) : matbase::Mask(photo.rgb.pixel_count(), 1);
  return resized_input(photo.rgb, object, size);
}

IsolatedInput isolated_input(const matbase::FloatImage& rgb, const matbase::Mask& object, int size, CropBackground background) {
  if (size < 1) throw std::invalid_argument("isolated_input: size must be at least 1");
  const std::optional<matbase::PixelBox> bounds = matbase::mask_bounds(object, rgb.width, rgb.height);
  if (!bounds) throw std::invalid_argument("isolated_input: the mask holds no pixel of the object");
  IsolatedInput isolated;
  isolated.crop = matbase::object_crop_square(*bounds);
  const float fill = background == CropBackground::White ? 1.0f : 0.0f;
  const matbase::FloatImage crop =
      matbase::crop_to_square(rgb, isolated.crop, std::vector<float>(static_cast<size_t>(rgb.channels), fill), object);
  matbase::FloatImage object_image(rgb.width, rgb.height, 1);
  for (size_t p = 0; p < object.size(); ++p) object_image.values[p] = object[p] != 0 ? 1.0f : 0.0f;
  const matbase::FloatImage crop_mask = matbase::crop_to_square(object_image, isolated.crop, {0.0f});
  matbase::Mask crop_object(crop_mask.values.size());
  for (size_t p = 0; p < crop_object.size(); ++p) crop_object[p] = crop_mask.values[p] > 0.0f;
  isolated.input = resized_input(crop, crop_object, size);
  return isolated;
}

}  // namespace matdataset
