#pragma once
// The names a dataset uses at its root, and the variant folders of a dataset on disk, for the
// tools that read one whoever wrote it (--verify, --preview).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace matdataset {

// The dataset's own entries at its root, beside the object folders.
inline constexpr const char* kConfigFolder = "config";        // the split files
inline constexpr const char* kPreviewFolder = "preview";      // --preview's contact sheets
inline constexpr const char* kPaperTexturesFolder = "paper_textures";  // paper_texture_layout
inline constexpr const char* kSegmentationMapFile = "material_segmentation_map.yaml";
// The split files in config/, each listing every frame once (docs/dataset_format.md, "Splits").
inline constexpr const char* kSplitFiles[] = {"object_disjoint_v1.yaml", "variance_disjoint_v1.yaml",
                                              "material_disjoint_v1.yaml", "paper_random_v1.yaml"};
// make_dataset's split that holds lighting out, written beside them since lighting setups exist
// (--verify reads it where it is, and does not ask older datasets for it).
inline constexpr const char* kLightingSplitFile = "lighting_disjoint_v1.yaml";

// What keeps `name` from naming an object's folder on every file system a dataset is copied to
// ("it is 300 bytes long, more than the 255 a file name may have"), or nothing.
std::optional<std::string> object_folder_problem(const std::string& name);

// <root>/<object>/<variant>/ folders holding `marker` ("images", "transforms.json"), sorted;
// the dataset's own folders are no objects. Throws matbase::InputError when `root` is no folder or holds
// no such variant.
std::vector<std::filesystem::path> variant_folders(const std::filesystem::path& root, const std::string& marker);

}  // namespace matdataset
