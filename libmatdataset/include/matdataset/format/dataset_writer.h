#pragma once
// Writing a dataset in the MatPredict repository's layout (docs/dataset_format.md), which its
// readers load unchanged, with its weak points fixed: one table of the eight per-frame maps, the
// maps of one frame from plain arrays, and the per-variant records (transforms.json,
// metadata.json, material_segmentation_map.json). Needs no renderer: make_dataset connects
// libmatrender's frames to it.
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace matdataset {

// The maps of a frame (the repository's seven, the sample count, in frames with surroundings the
// region, and where asked for the image in floats), in the order a frame's files are staged:
// images/ last, because readers look for it first, so a frame whose image exists has every other
// map too.
enum class DatasetMap { Albedo, Orm, Depth, NormalMaterial, NormalObject, Label, SampleCount, Region, HdrImages, Images };
constexpr size_t kDatasetMapCount = 10;

// Which frames have a map: every frame, frames with surroundings, or those of a dataset made with
// render.hdr_images.
enum class MapPresence { Always, WithSurroundings, WithHdrImages };

// What a variant's frames hold beyond the maps every frame has.
struct FrameContents {
  bool surroundings = false;  // the region map
  bool hdr_images = false;    // the image in linear floats too
};

// The region map's values: what the hit nearest the pixel centre is on.
enum class FrameRegion : int32_t { Background = 0, Surroundings = 1, Target = 2 };

// The most camera samples the 16-bit sample count map holds.
constexpr int32_t kMaxSampleCount = 65535;

struct DatasetMapInfo {
  DatasetMap map;
  const char* folder;          // the variant's subfolder
  const char* extension;       // ".png" or ".exr"
  int channels;                // as written
  const char* transforms_key;  // the frame's key for the file in transforms.json
  bool repository;             // the MatPredict repository writes it too (not: ours only)
  MapPresence presence;
  const char* content;         // one line for the docs
};
const std::array<DatasetMapInfo, kDatasetMapCount>& dataset_maps();
// Whether a frame of `contents` has the map.
inline bool frame_has_map(const DatasetMapInfo& info, const FrameContents& contents) {
  switch (info.presence) {
    case MapPresence::Always: return true;
    case MapPresence::WithSurroundings: return contents.surroundings;
    case MapPresence::WithHdrImages: return contents.hdr_images;
  }
  return true;
}
// The table as the markdown of docs/dataset_format.md (a test holds the docs to it).
std::string dataset_maps_markdown();

// "007" for frame 7 of 120, "0007" of 1500: zero-padded to the digits of the largest index and
// at least 3, so stems sort in frame order for any count (the repository's 3 digits broke past
// 999, its W18). Variant folders take the same padding after "var".
std::string frame_stem(size_t index, size_t count);
std::string variant_folder_name(size_t index, size_t count);

// One frame's maps as the renderer's AOVs hold them: row-major, row 0 at the top, channels
// interleaved, every array width x height (x channels).
struct FrameMaps {
  int width = 0;
  int height = 0;
  std::vector<float> color;              // linear RGB premultiplied by coverage (transparent background)
  std::vector<float> coverage;           // the fraction of the pixel's samples that hit a surface
  std::vector<float> base_color;         // linear RGB, the mean over the samples that hit
  std::vector<float> roughness;          // the mean over the hits
  std::vector<float> metallic;           // the mean over the hits
  std::vector<float> ambient_occlusion;  // the mean over the hits, in [0, 1]
  std::vector<float> normal_world;       // unit XYZ, world space, shading normal
  std::vector<float> normal_tangent;     // unit XYZ, the normal map's tangent space
  std::vector<float> depth;              // metres along the camera axis, from one hit sample
  std::vector<int32_t> label;            // label id from one hit sample, 0 where it is not on the target
  // FrameRegion of the hit sample the label comes from, per pixel; empty for an object alone
  // (then the region map is not written).
  std::vector<int32_t> region;
  std::vector<int32_t> sample_count;     // camera samples the pixel took (adaptive sampling stops some early)
  double exposure_stops = 0.0;           // applied to the image before encoding
  // The image's background is the world camera rays see: its alpha is 1, not the coverage.
  bool opaque_background = false;
  // Write the image in linear floats too (images_hdr/).
  bool hdr_image = false;

  FrameContents contents() const { return {!region.empty(), hdr_image}; }
};

// Writes the frame's files (eight, nine with a region or the HDR image, ten with both) into `variant_folder`'s map folders (made if missing), each
// under a temporary name renamed when all are written, images/ last (matbase::AtomicFileSet):
// after a crash a frame is there whole or not at all. Throws std::invalid_argument for arrays
// of the wrong size, a label beyond 255, a region that is no FrameRegion or that disagrees with the label (a
// label off the target, the target without one), or a sample count outside [1, 65535], std::runtime_error naming the file a write failed on.
void write_frame_maps(const std::filesystem::path& variant_folder, const std::string& stem, const FrameMaps& maps);

// Whether every map of the frame is there and decodes whole at width x height with its channel
// count: what a resumed run checks before skipping a frame, so a file damaged or cut short
// since is rendered again.
// `contents`: the maps the frame has beyond every frame's.
bool frame_is_complete(const std::filesystem::path& variant_folder, const std::string& stem, int width, int height,
                       const FrameContents& contents);

// A pinhole camera's intrinsics in pixels (OpenCV's convention: fl_x = fx, cx = principal point
// from the left edge of the image, pixel centres at half-integers).
struct CameraIntrinsics {
  int width = 0, height = 0;
  double fl_x = 0.0, fl_y = 0.0, cx = 0.0, cy = 0.0;
};
// Square pixels, the principal point at the image centre, and the given vertical field of view.
CameraIntrinsics pinhole_intrinsics(int width, int height, double vertical_fov);

struct FramePose {
  std::string stem;
  // Camera to world, rows of the 4 x 4 matrix, Blender's camera axes (+X right, +Y up, looking
  // down -Z), world Z up, metres.
  std::array<std::array<double, 4>, 4> camera_to_world{};
  // The frame's lighting as a JSON object (make_dataset's frame_lighting.h), recorded under
  // "lighting"; empty: none recorded.
  std::string lighting_json;
  // What stands around the object in the frame (make_dataset's distractors), as a JSON object,
  // recorded under "surroundings"; empty: none recorded.
  std::string surroundings_json;
};

// transforms.json: the repository's keys (camera_angle_x, and per frame transform_matrix,
// file_path, file_path_albedo, file_path_normal, file_path_orm, file_path_depth, rotation,
// envmap) plus what it lacks: camera_angle_y, fl_x, fl_y, cx, cy, w, h, and the paths of the
// label and normal_mat maps.
// The frames' region and HDR images are listed where `contents` has them (file_path_region,
// file_path_hdr).
void write_transforms(const std::filesystem::path& variant_folder, const CameraIntrinsics& intrinsics,
                      const std::vector<FramePose>& frames, const FrameContents& contents = {});

// The material of one slot of a variant.
struct SlotMaterial {
  std::string slot;      // the slot's key ("mat1", "all")
  std::string material;  // the material's name ("wood_lacquered_3", a MatSynth folder's name)
  int32_t label_id = 0;  // its class in matgeom's table (never 0: a slot must have a class)
};

struct VariantMetadata {
  std::vector<SlotMaterial> materials;  // one per slot
  int width = 0, height = 0, samples = 0;
  // A JSON object with everything else needed to render a frame again (the object and its seed,
  // the materials and their seeds, the camera grid, the lights, the render settings, the
  // software's version), as the tool that rendered describes it: stored under "provenance".
  std::string provenance_json;
  FrameContents contents;  // the maps the frames have beyond every frame's (output_structure lists them)
};

// metadata.json: the repository's variant_map, used_materials and render_summary, plus
// "provenance". Throws std::invalid_argument for a slot whose label is not a class of the table
// or is 0 (the repository silently labelled such slots background, its W12), or provenance that
// is not a JSON object.
void write_variant_metadata(const std::filesystem::path& variant_folder, const VariantMetadata& metadata);
// The text write_variant_metadata writes, to compare with a file already there.
std::string variant_metadata_text(const VariantMetadata& metadata);

// material_segmentation_map.json in the variant (id_to_material_family, material_family_to_id)
// and material_segmentation_map.yaml at the root, both listing every class of matgeom's table.
void write_segmentation_map_json(const std::filesystem::path& variant_folder);
void write_segmentation_map_yaml(const std::filesystem::path& root);

}  // namespace matdataset
