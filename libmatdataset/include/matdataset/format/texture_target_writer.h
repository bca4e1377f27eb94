#pragma once
// Writing the paper's texture-target layout (docs/matpredict_repository.md, section 7;
// docs/dataset_format.md): screenshots cropped to the object on white,
// <root>/rendered_cropped/<object>/<material>/<stem>.png, and one reference map per material and
// parameter, <root>/ground_truth_basecolour/<material>.png, ground_truth_roughness/,
// ground_truth_metallic/ and ground_truth_normal/, which libmatdataset's reader loads
// (matdataset/format/dataset_index.h). Every file is written under a temporary name and renamed.
#include <filesystem>
#include <optional>
#include <string>

#include "matbase/image/image_pixels.h"
#include "matdataset/format/dataset_writer.h"

namespace matdataset {

// A material's flat maps: its base colour (sRGB-encoded RGB), roughness and metallic (linear,
// grey in three channels, as the paper's PNGs), and its tangent-space normal map if it has one.
struct MaterialReferences {
  matbase::ImagePixels base_color, roughness, metallic;
  std::optional<matbase::ImagePixels> normal;
};

// Throws std::invalid_argument for an image that is not well formed (matbase::is_well_formed).
void write_texture_target_references(const std::filesystem::path& root, const std::string& material,
                                     const MaterialReferences& references);

// The frame's image cropped to a square around the object (its covered pixels' bounding box and
// a margin of 4 %: matbase::object_crop_square), composited over white in linear light and sRGB-encoded, as the paper's
// preprocessing keyed its renders onto white. A frame with no object is kept whole.
void write_texture_target_screenshot(const std::filesystem::path& root, const std::string& object,
                                     const std::string& material, const std::string& stem, const FrameMaps& maps);

// The screenshot's path, and whether it is there and decodes whole (a resumed run's check).
std::filesystem::path texture_target_screenshot_path(const std::filesystem::path& root, const std::string& object,
                                                     const std::string& material, const std::string& stem);
bool texture_target_screenshot_is_complete(const std::filesystem::path& path);

}  // namespace matdataset
