#include "matlearn/sample_reader.h"

#include <cmath>
#include <stdexcept>

#include <OpenImageIO/imageio.h>

#include "data/resample.h"

namespace matlearn {
namespace {

namespace fs = std::filesystem;

struct Decoded {
  int width = 0, height = 0, channels = 0;
  std::vector<float> values;
};

// Every channel of an image file as floats, colour as stored (not premultiplied by alpha);
// 8-bit values map to [0, 1].
Decoded decode(const fs::path& path) {
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path.string(), &config);
  if (!in) throw std::runtime_error("cannot read " + path.string() + ": " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  Decoded d{spec.width, spec.height, spec.nchannels, {}};
  d.values.resize(static_cast<size_t>(d.width) * static_cast<size_t>(d.height) * static_cast<size_t>(d.channels));
  if (!in->read_image(0, 0, 0, d.channels, OIIO::TypeDesc::FLOAT, d.values.data()))
    throw std::runtime_error("cannot decode " + path.string() + ": " + in->geterror());
  return d;
}

// The first `channels` channels (a grey image repeated), as PIL's convert("RGB") or convert("L").
Image channels_of(const Decoded& d, int first, int channels) {
  Image image(d.width, d.height, channels);
  for (size_t p = 0; p < image.pixel_count(); ++p)
    for (int c = 0; c < channels; ++c)
      image.values[p * static_cast<size_t>(channels) + static_cast<size_t>(c)] =
          d.values[p * static_cast<size_t>(d.channels) + static_cast<size_t>(d.channels >= first + channels ? first + c : 0)];
  return image;
}

float srgb_to_linear(float v) {
  return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

// 0.5 n + 0.5 values resized as unit vectors (see read_sample's comment).
Image resize_normal_map(const Image& encoded, const std::vector<float>& weights, int size) {
  Image decoded = encoded;
  for (float& v : decoded.values) v = 2.0f * v - 1.0f;
  Image resized = resize_bilinear_weighted(decoded, weights, size, size);
  for (size_t p = 0; p < resized.pixel_count(); ++p) {
    float* n = &resized.values[p * 3];
    const float length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const float scale = length > 0.0f ? 1.0f / length : 0.0f;
    for (int c = 0; c < 3; ++c) n[c] = 0.5f * n[c] * scale + 0.5f;
  }
  return resized;
}

void check_same_size(const Decoded& d, const Decoded& reference, const fs::path& path) {
  if (d.width != reference.width || d.height != reference.height)
    throw std::runtime_error(path.string() + " is " + std::to_string(d.width) + "x" + std::to_string(d.height) +
                             " but the sample's image is " + std::to_string(reference.width) + "x" +
                             std::to_string(reference.height));
}

}  // namespace

MaterialSample read_sample(const fs::path& root, const SampleId& id, const SampleSettings& settings) {
  if (settings.size < 1) throw std::invalid_argument("read_sample: size must be at least 1");
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
    for (float& v : albedo_rgb.values) v = srgb_to_linear(v);
  sample.albedo = resize_bilinear_weighted(albedo_rgb, weights, s, s);
  sample.roughness = resize_bilinear_weighted(channels_of(orm, 1, 1), weights, s, s);
  sample.metallic = resize_bilinear_weighted(channels_of(orm, 2, 1), weights, s, s);
  if (settings.read_normal) {
    const fs::path normal_path = dir / "normal_obj" / file;
    const Decoded normal = decode(normal_path);
    check_same_size(normal, image, normal_path);
    if (normal.channels < 3) throw std::runtime_error(normal_path.string() + " has fewer than 3 channels");
    sample.normal = resize_normal_map(channels_of(normal, 0, 3), weights, s);
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
