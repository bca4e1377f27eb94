#include "matdataset/format/dataset_writer.h"

#include <algorithm>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "matbase/file/atomic_file.h"
#include "matbase/image/image_writing.h"
#include "matdataset/format/decoded_image.h"

namespace matdataset {
namespace {

namespace fs = std::filesystem;

// The encodings, one line each, are the docs' table (docs/dataset_format.md, "Per frame").
constexpr std::array<DatasetMapInfo, kDatasetMapCount> kMaps = {{
    {DatasetMap::Albedo, "albedo", ".png", 4, "file_path_albedo", true, MapPresence::Always,
     "base colour, sRGB-encoded 8-bit, straight alpha = coverage"},
    {DatasetMap::Orm, "ORM", ".png", 4, "file_path_orm", true, MapPresence::Always,
     "R ambient occlusion, G roughness, B metallic, linear 8-bit; A = 255 where a surface is"},
    {DatasetMap::Depth, "depth", ".exr", 4, "file_path_depth", true, MapPresence::Always,
     "R = G = B = depth along the camera axis in metres (32-bit float, never scaled by coverage); A = coverage"},
    {DatasetMap::NormalMaterial, "normal_mat", ".png", 4, "file_path_normal_mat", true, MapPresence::Always,
     "the normal map's tangent-space normal, 0.5 n + 0.5, 8-bit; A = 255 where a surface is"},
    {DatasetMap::NormalObject, "normal_obj", ".png", 4, "file_path_normal", true, MapPresence::Always,
     "world-space shading normal, 0.5 n + 0.5, 8-bit; A = 255 where a surface is"},
    {DatasetMap::Label, "label", ".png", 1, "file_path_label", true, MapPresence::Always,
     "material class id (8-bit grey) of one sample per pixel, nonzero exactly where that sample is on the target "
     "object: the object mask (for an object alone, exactly where coverage > 0)"},
    {DatasetMap::SampleCount, "sample_count", ".png", 1, "file_path_sample_count", false, MapPresence::Always,
     "camera samples the pixel took (16-bit grey, every pixel): the render's samples, or fewer where adaptive sampling stopped it"},
    {DatasetMap::Region, "region", ".png", 1, "file_path_region", false, MapPresence::WithSurroundings,
     "frames with surroundings only: what the label's sample is on, 0 background, 1 surroundings, 2 the target "
     "(8-bit grey); 2 exactly where the label is nonzero"},
    {DatasetMap::HdrImages, "images_hdr", ".exr", 4, "file_path_hdr", false, MapPresence::WithHdrImages,
     "datasets made with render.hdr_images only: the render in 32-bit floats, scene-linear Rec.709 RGB before "
     "the exposure images/ applies, premultiplied by A = coverage (1 over a "
     "background camera rays see)"},
    {DatasetMap::Images, "images", ".png", 4, "file_path", true, MapPresence::Always,
     "the render, sRGB-encoded 8-bit, straight alpha = coverage"},
}};

size_t digits(size_t n) {
  size_t d = 1;
  while (n >= 10) n /= 10, ++d;
  return d;
}

template <typename T>
void check_size(const std::vector<T>& values, size_t expected, const char* name) {
  if (values.size() != expected)
    throw std::invalid_argument(std::string("frame maps: ") + name + " holds " + std::to_string(values.size()) +
                                " values, expected " + std::to_string(expected));
}

void check_sizes(const FrameMaps& maps) {
  if (maps.width <= 0 || maps.height <= 0) throw std::invalid_argument("frame maps: the image has no pixels");
  const size_t n = static_cast<size_t>(maps.width) * static_cast<size_t>(maps.height);
  check_size(maps.color, 3 * n, "color");
  check_size(maps.coverage, n, "coverage");
  check_size(maps.base_color, 3 * n, "base_color");
  check_size(maps.roughness, n, "roughness");
  check_size(maps.metallic, n, "metallic");
  check_size(maps.ambient_occlusion, n, "ambient_occlusion");
  check_size(maps.normal_world, 3 * n, "normal_world");
  check_size(maps.normal_tangent, 3 * n, "normal_tangent");
  check_size(maps.depth, n, "depth");
  check_size(maps.label, n, "label");
  check_size(maps.sample_count, n, "sample_count");
  if (maps.region.empty()) return;
  check_size(maps.region, n, "region");
  for (size_t p = 0; p < n; ++p) {
    const int32_t region = maps.region[p];
    if (region < static_cast<int32_t>(FrameRegion::Background) || region > static_cast<int32_t>(FrameRegion::Target))
      throw std::invalid_argument("frame maps: region " + std::to_string(region) + " is none of 0, 1, 2");
    if ((region == static_cast<int32_t>(FrameRegion::Target)) != (maps.label[p] > 0 && maps.coverage[p] > 0.0f))
      throw std::invalid_argument("frame maps: at pixel " + std::to_string(p) + " the region (" + std::to_string(region) +
                                  ") and the label (" + std::to_string(maps.label[p]) + ") disagree on the target");
  }
}

// A data map's pixel: the values where the object is, with A = 1 so that readers which
// premultiply PNG colour by alpha on reading (OpenImageIO does) get the values unchanged; all 0
// where nothing is.
std::vector<float> covered_rgba(const FrameMaps& maps, const std::function<void(size_t, float*)>& rgb) {
  const size_t n = maps.coverage.size();
  std::vector<float> rgba(4 * n, 0.0f);
  for (size_t p = 0; p < n; ++p) {
    if (maps.coverage[p] <= 0.0f) continue;
    rgb(p, &rgba[4 * p]);
    rgba[4 * p + 3] = 1.0f;
  }
  return rgba;
}

std::vector<float> encoded_normals(const FrameMaps& maps, const std::vector<float>& normal) {
  return covered_rgba(maps, [&](size_t p, float* out) {
    for (int c = 0; c < 3; ++c) out[c] = 0.5f * normal[3 * p + static_cast<size_t>(c)] + 0.5f;
  });
}

fs::path map_file(const fs::path& variant_folder, const DatasetMapInfo& info, const std::string& stem) {
  return variant_folder / info.folder / (stem + info.extension);
}

}  // namespace

const std::array<DatasetMapInfo, kDatasetMapCount>& dataset_maps() { return kMaps; }

std::string dataset_maps_markdown() {
  std::string text = "| folder | file | channels | transforms.json key | content |\n|---|---|---:|---|---|\n";
  for (const DatasetMapInfo& info : kMaps)
    text += std::string("| `") + info.folder + "/` | `<stem>" + info.extension + "` | " + std::to_string(info.channels) +
            " | `" + info.transforms_key + "` | " + info.content + " |\n";
  return text;
}

std::string frame_stem(size_t index, size_t count) {
  const size_t width = std::max<size_t>(3, digits(count > 0 ? count - 1 : 0));
  const std::string number = std::to_string(index);
  return std::string(width > number.size() ? width - number.size() : 0, '0') + number;
}

std::string variant_folder_name(size_t index, size_t count) { return "var" + frame_stem(index, count); }

void write_frame_maps(const fs::path& variant_folder, const std::string& stem, const FrameMaps& maps) {
  check_sizes(maps);
  const int w = maps.width, h = maps.height;
  const size_t n = maps.coverage.size();
  for (const int32_t label : maps.label)
    if (label < 0 || label > 255)
      throw std::invalid_argument("frame maps: label " + std::to_string(label) + " does not fit the 8-bit label map");
  for (const int32_t count : maps.sample_count)
    if (count < 1 || count > kMaxSampleCount)
      throw std::invalid_argument("frame maps: sample count " + std::to_string(count) +
                                  " does not fit the 16-bit sample count map (1 to 65535)");
  const FrameContents contents = maps.contents();
  for (const DatasetMapInfo& info : kMaps)
    if (frame_has_map(info, contents)) fs::create_directories(variant_folder / info.folder);
  matbase::AtomicFileSet set(map_file(variant_folder, kMaps.back(), stem));
  auto path = [&](DatasetMap map) { return map_file(variant_folder, kMaps[static_cast<size_t>(map)], stem).string(); };

  // The albedo is the mean over hits; the display writer un-premultiplies, so premultiply it.
  std::vector<float> albedo(3 * n);
  for (size_t i = 0; i < 3 * n; ++i) albedo[i] = maps.base_color[i] * maps.coverage[i / 3];
  matbase::write_display_png(path(DatasetMap::Albedo), w, h, albedo.data(), maps.coverage.data(), 0.0, &set);

  const std::vector<float> orm = covered_rgba(maps, [&](size_t p, float* out) {
    out[0] = maps.ambient_occlusion[p];
    out[1] = maps.roughness[p];
    out[2] = maps.metallic[p];
  });
  matbase::write_data_png(path(DatasetMap::Orm), w, h, 4, orm.data(), 255.0, 0.0, false, &set);

  std::vector<float> depth(4 * n);
  for (size_t p = 0; p < n; ++p) {
    depth[4 * p] = depth[4 * p + 1] = depth[4 * p + 2] = maps.coverage[p] > 0.0f ? maps.depth[p] : 0.0f;
    depth[4 * p + 3] = maps.coverage[p];
  }
  matbase::write_exr(path(DatasetMap::Depth), w, h, {"R", "G", "B", "A"}, depth.data(), &set);

  const std::vector<float> normal_mat = encoded_normals(maps, maps.normal_tangent);
  matbase::write_data_png(path(DatasetMap::NormalMaterial), w, h, 4, normal_mat.data(), 255.0, 0.0, false, &set);
  const std::vector<float> normal_obj = encoded_normals(maps, maps.normal_world);
  matbase::write_data_png(path(DatasetMap::NormalObject), w, h, 4, normal_obj.data(), 255.0, 0.0, false, &set);

  std::vector<float> label(n);
  for (size_t p = 0; p < n; ++p) label[p] = maps.coverage[p] > 0.0f ? static_cast<float>(maps.label[p]) : 0.0f;
  matbase::write_data_png(path(DatasetMap::Label), w, h, 1, label.data(), 1.0, 0.0, false, &set);

  const std::vector<float> sample_count(maps.sample_count.begin(), maps.sample_count.end());
  matbase::write_data_png(path(DatasetMap::SampleCount), w, h, 1, sample_count.data(), 1.0, 0.0, true, &set);

  if (contents.surroundings) {
    const std::vector<float> region(maps.region.begin(), maps.region.end());
    matbase::write_data_png(path(DatasetMap::Region), w, h, 1, region.data(), 1.0, 0.0, false, &set);
  }

  // Over a background camera rays see, every pixel is opaque (alpha 1, not the coverage).
  const std::vector<float> opaque = maps.opaque_background ? std::vector<float>(n, 1.0f) : std::vector<float>();
  if (contents.hdr_images) {
    std::vector<float> rgba(4 * n);
    for (size_t p = 0; p < n; ++p) {
      for (size_t c = 0; c < 3; ++c) rgba[4 * p + c] = maps.color[3 * p + c];
      rgba[4 * p + 3] = maps.opaque_background ? 1.0f : maps.coverage[p];
    }
    matbase::write_exr(path(DatasetMap::HdrImages), w, h, {"R", "G", "B", "A"}, rgba.data(), &set);
  }
  matbase::write_display_png(path(DatasetMap::Images), w, h, maps.color.data(),
                             maps.opaque_background ? opaque.data() : maps.coverage.data(), maps.exposure_stops, &set);
  set.commit();
}

bool frame_is_complete(const fs::path& variant_folder, const std::string& stem, int width, int height,
                       const FrameContents& contents) {
  for (const DatasetMapInfo& info : kMaps) {
    if (!frame_has_map(info, contents)) continue;
    const fs::path file = map_file(variant_folder, info, stem);
    std::error_code error;
    if (!fs::is_regular_file(file, error)) return false;
    try {
      const matbase::FloatImage map = decode(file);
      if (map.width != width || map.height != height || map.channels != info.channels) return false;
    } catch (const std::runtime_error&) {
      return false;  // damaged or cut short: the frame is rendered again
    }
  }
  return true;
}

}  // namespace matdataset
