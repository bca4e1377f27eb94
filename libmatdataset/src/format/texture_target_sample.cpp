#include "format/texture_target_sample.h"

#include <map>
#include <mutex>
#include <string>

#include "matbase/image/srgb.h"
#include "matdataset/format/decoded_image.h"
#include "matdataset/format/resample.h"

namespace matdataset {
namespace {

namespace fs = std::filesystem;

enum class ReferenceKind { display_colour, linear_colour, grey, unit_vectors };

// The reference map at `path` for `kind`, resized to size x size, decoded once per process.
matbase::FloatImage reference_map(const fs::path& path, ReferenceKind kind, int size) {
  static std::mutex mutex;
  static std::map<std::string, matbase::FloatImage> cache;
  const std::string key = path.string() + "|" + std::to_string(static_cast<int>(kind)) + "|" + std::to_string(size);
  {
    std::lock_guard<std::mutex> lock(mutex);
    const auto found = cache.find(key);
    if (found != cache.end()) return found->second;
  }
  const matbase::FloatImage decoded = decode_finite(path);
  matbase::FloatImage map = channels_of(decoded, 0, kind == ReferenceKind::grey ? 1 : 3);
  if (kind == ReferenceKind::linear_colour)
    for (float& v : map.values) v = matbase::srgb_to_linear(v);
  const matbase::FloatImage resized = kind == ReferenceKind::unit_vectors
                            ? resize_unit_vectors(map, std::vector<float>(map.pixel_count(), 1.0f), size, size)
                            : resize_bilinear(map, size, size);
  std::lock_guard<std::mutex> lock(mutex);
  return cache.emplace(key, resized).first->second;
}

// The screenshot of the sample.
fs::path screenshot_file(const fs::path& root, const SampleId& id) {
  return root / "rendered_cropped" / id.object / id.variant / (id.stem + ".png");
}

// The material's reference map in `folder` ("ground_truth_roughness").
fs::path reference_file(const fs::path& root, const char* folder, const SampleId& id) {
  return root / folder / (id.variant + ".png");
}

}  // namespace

std::vector<fs::path> texture_target_files(const fs::path& root, const SampleId& id, const SampleSettings& settings) {
  std::vector<fs::path> files = {screenshot_file(root, id), reference_file(root, "ground_truth_basecolour", id),
                                 reference_file(root, "ground_truth_roughness", id)};
  if (settings.read_metallic) files.push_back(reference_file(root, "ground_truth_metallic", id));
  if (settings.read_normal) files.push_back(reference_file(root, "ground_truth_normal", id));
  return files;
}

MaterialSample read_texture_target_sample(const fs::path& root, const SampleId& id, const SampleSettings& settings) {
  const int s = settings.size;
  MaterialSample sample;
  sample.input = resize_bilinear(channels_of(decode_finite(screenshot_file(root, id)), 0, 3), s, s);
  sample.albedo = reference_map(reference_file(root, "ground_truth_basecolour", id),
                                settings.linear_albedo ? ReferenceKind::linear_colour : ReferenceKind::display_colour, s);
  sample.roughness = reference_map(reference_file(root, "ground_truth_roughness", id), ReferenceKind::grey, s);
  const fs::path metallic = reference_file(root, "ground_truth_metallic", id);
  if (settings.read_metallic || fs::is_regular_file(metallic)) sample.metallic = reference_map(metallic, ReferenceKind::grey, s);
  if (settings.read_normal)
    sample.normal = reference_map(reference_file(root, "ground_truth_normal", id), ReferenceKind::unit_vectors, s);
  sample.material_id.assign(static_cast<size_t>(s) * static_cast<size_t>(s), 1);
  sample.mask.assign(sample.material_id.size(), 1);
  return sample;
}

}  // namespace matdataset
