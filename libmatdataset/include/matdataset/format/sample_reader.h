#pragma once
// One sample of a MatPredict dataset (matdataset/format/dataset_index.h), decoded and resized the way the
// repository's loader does it (docs/matpredict_repository.md, section 2), with its
// weak points fixed where they touch the data: targets are resized with the object mask as
// weights, so the background does not bleed into the silhouette (W16), and the albedo can be
// decoded to linear values for a loss in linear space (W5).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "matbase/image/float_image.h"
#include "matbase/image/object_crop.h"
#include "matdataset/format/dataset_index.h"

namespace matdataset {

struct SampleSettings {
  int size = 224;              // maps are resized to size x size
  bool linear_albedo = false;  // sRGB-decode the stored (display-encoded) albedo
  bool read_normal = false;    // read normal_obj/<stem>.png as well; then it must exist
  bool read_metallic = false;  // the paper's layout: ground_truth_metallic/<material>.png must exist
  // The classes of a network's segmentation head, 0 for none. With a head the label is a target:
  // label/<stem>.png must exist and every id in it be below this.
  int64_t material_classes = 0;
};

struct MaterialSample {
  matbase::FloatImage input;                       // RGB in [0, 1] as stored, alpha dropped; size x size x 3
  matbase::FloatImage albedo;                      // size x size x 3
  matbase::FloatImage roughness;                   // ORM green; size x size x 1
  matbase::FloatImage metallic;                    // ORM blue; size x size x 1
  matbase::FloatImage normal;                      // normal_obj as stored, 0.5 n + 0.5; size x size x 3; empty
                                     // unless SampleSettings::read_normal
  std::vector<int32_t> material_id;  // label ids, nearest-resized (0 = background)
  matbase::Mask mask;                         // material_id > 0; every pixel when there is no label file
  bool has_label = false;
};

// In the paper's texture-target layout the maps are the material's reference maps, resized whole
// (data/texture_target_sample.h): every pixel is in the mask, there is no label, and metallic is
// empty unless the material has a ground_truth_metallic map.
// Colour channels are read as stored, whatever the alpha (PIL's convert("RGB"); OpenImageIO
// would premultiply PNG colour by alpha). A normal map is resized as unit vectors: decoded,
// resized with the object mask as weights, renormalised and encoded again, so a resized normal
// still has length 1 (0.5 where no object pixel reaches).
// Label maps are read as the integers written (8- or 16-bit). Throws DatasetError
// (matdataset/format/dataset_error.h) naming the file and the problem: a map missing or unreadable, of
// another size than the image, with too few channels (ORM's roughness and metallic, a normal's
// three), holding a NaN or an infinity, or a label id beyond the network's classes.
MaterialSample read_sample(const std::filesystem::path& root, const SampleId& id, const SampleSettings& settings);

// The files read_sample reads for `id` with `settings`, the optional label aside.
std::vector<std::filesystem::path> sample_files(const std::filesystem::path& root, const SampleId& id,
                                                const SampleSettings& settings);

// Throws DatasetError, opening with `context` (what the samples are: a dataset folder, a split),
// naming how many files the samples lack and the first few, when any of sample_files is not a
// regular file; and when some samples have a label map and others not, since the label is each
// frame's object mask: without it a frame's background would count as object. Checked before a
// run, so a run never trains or scores on fewer frames than it was given.
void require_sample_files(const std::filesystem::path& root, const std::vector<SampleId>& samples,
                          const SampleSettings& settings, const std::string& context);

// One image to run a network on, outside any dataset.
struct InputImage {
  matbase::FloatImage rgb;  // size x size x 3 in [0, 1], resized as the samples' inputs are
  matbase::Mask mask;  // the object, nearest-resized
};

// The object mask comes from `mask_path` when it is not empty (any nonzero value is the object,
// so a label map of ids 1..7 serves, where the repository's "> 0.5 after / 255" made it all
// background: its W17), else from the image's alpha channel (> 0), else it is every pixel.
// Throws DatasetError naming the file.
InputImage read_input_image(const std::filesystem::path& image_path, const std::filesystem::path& mask_path, int size);

// A photograph or a frame to isolate an object in: its RGB (display-encoded as stored; a grey
// image in all three channels) and the object mask `mask_path` gives (any nonzero value) when it
// is not empty, else the image's alpha (> 0) when some pixel is transparent; none otherwise (an
// alpha opaque everywhere says nothing of the object). Throws DatasetError naming the file.
struct PhotoInput {
  matbase::FloatImage rgb;
  std::optional<matbase::Mask> mask;
};
PhotoInput read_photo(const std::filesystem::path& image_path, const std::filesystem::path& mask_path);

// The object an image's alpha marks (the last channel of a grey-alpha or RGBA image, > 0), when
// some pixel is transparent; none for an image without alpha or opaque everywhere.
std::optional<matbase::Mask> alpha_mask(const matbase::FloatImage& image);

// What an isolated object is composited on: black, what the dataset's images hold where nothing
// was hit (the trainer drops their alpha, so its networks learn on black), or white, what the
// paper's preprocessing and the texture-target screenshots key onto.
enum class CropBackground { Black, White };

struct IsolatedInput {
  InputImage input;          // the crop, resized; mask: the object in it
  matbase::CropSquare crop;  // where the crop lies in the image, in its pixels
};

// The network's input for the object `object` marks in `rgb`: the square around it
// (matbase::object_crop_square), every pixel outside the object set to `background`, resized to
// size x size as samples' inputs are. Throws std::invalid_argument for an empty mask.
IsolatedInput isolated_input(const matbase::FloatImage& rgb, const matbase::Mask& object, int size, CropBackground background);

}  // namespace matdataset
