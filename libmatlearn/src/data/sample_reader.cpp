#include "matlearn/sample_reader.h"

#include <cmath>
#include <stdexcept>

#include "matlearn/decoded_image.h"
#include "data/resample.h"
#include "data/texture_target_sample.h"
#include "matgeom/srgb.h"

namespace matlearn {

namespace fs = std::filesystem;

MaterialSample read_sample(const fs::path& root, const SampleId& id, const SampleSettings& settings) {
  if (settings.size < 1) throw std::invalid_argument("read_sample: size must be at least 1");
  if (dataset_layout(root) == DatasetLayout::paper_textures) return read_texture_target_sample(root, id, settings);
  const fs::path dir = root / id.object / id.variant;
  const std::string file = id.stem + ".png";
  const Decoded image = decode(dir / "images" / file);
  const Decoded albedo = decode(dir / "albedo" / file);
  const Decoded orm = decode(dir / "ORM" / file);
  check_same_size(albedo, image, dir / "albedo" / file);
  check_same_size(orm, image, dir / "ORM" / file);
  if (orm.channels < 3) throw std::runtime_error((dir / "ORM" / file).string() + " has fewer than 3 channels");

  MaterialSample sample;
  const int s = settings.size;
  // Label ids and the object mask at full resolution; the targets' resize weights.
  std::vector<int32_t> ids(static_cast<size_t>(image.width) * static_cast<size_t>(image.height), 1);
  const fs::path label_path = dir / "label" / file;
  sample.has_label = fs::is_regular_file(label_path);
  if (sample.has_label) {
    const Decoded label = decode(label_path);
    check_same_size(label, image, label_path);
    for (size_t p = 0; p < ids.size(); ++p)
      ids[p] = static_cast<int32_t>(std::lround(label.values[p * static_cast<size_t>(label.channels)] * 255.0f));
  }
  std::vector<float> weights(ids.size());
  for (size_t p = 0; p < ids.size(); ++p) weights[p] = ids[p] > 0 ? 1.0f : 0.0f;

  sample.input = resize_bilinear(channels_of(image, 0, 3), s, s);
  Image albedo_rgb = channels_of(albedo, 0, 3);
  if (settings.linear_albedo)
    for (float& v : albedo_rgb.values) v = matgeom::srgb_to_linear(v);
  sample.albedo = resize_bilinear_weighted(albedo_rgb, weights, s, s);
  sample.roughness = resize_bilinear_weighted(channels_of(orm, 1, 1), weights, s, s);
  sample.metallic = resize_bilinear_weighted(channels_of(orm, 2, 1), weights, s, s);
  if (settings.read_normal) {
    const fs::path normal_path = dir / "normal_obj" / file;
    const Decoded normal = decode(normal_path);
    check_same_size(normal, image, normal_path);
    if (normal.channels < 3) throw std::runtime_error(normal_path.string() + " has fewer than 3 channels");
    sample.normal = resize_unit_vectors(channels_of(normal, 0, 3), weights, s, s);
  }
  sample.material_id = resize_nearest(ids, image.width, image.height, s, s);
  sample.mask.resize(sample.material_id.size());
  for (size_t p = 0; p < sample.mask.size(); ++p) sample.mask[p] = sample.material_id[p] > 0;
  return sample;
}

InputImage read_input_image(const fs::path& image_path, const fs::path& mask_path, int size) {
  if (size < 1) throw std::invalid_argument("read_input_image: size must be at least 1");
  const Decoded image = decode(image_path);
  std::vector<int32_t> object(static_cast<size_t>(image.width) * static_cast<size_t>(image.height), 1);
  if (!mask_path.empty()) {
    const Decoded mask = decode(mask_path);
    check_same_size(mask, image, mask_path);
    for (size_t p = 0; p < object.size(); ++p) object[p] = mask.values[p * static_cast<size_t>(mask.channels)] > 0.0f;
  } else if (image.channels == 4 || image.channels == 2) {
    for (size_t p = 0; p < object.size(); ++p)
      object[p] = image.values[p * static_cast<size_t>(image.channels) + static_cast<size_t>(image.channels - 1)] > 0.0f;
  }
  InputImage input;
  input.rgb = resize_bilinear(channels_of(image, 0, 3), size, size);
  const std::vector<int32_t> resized = resize_nearest(object, image.width, image.height, size, size);
  input.mask.assign(resized.begin(), resized.end());
  return input;
}

}  // namespace matlearn
