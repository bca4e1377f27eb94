#pragma once
// The variant folders of a dataset on disk, for the tools that read one whoever wrote it
// (--verify, --preview).
#include <filesystem>
#include <string>
#include <vector>

namespace make_dataset {

// <root>/<object>/<variant>/ folders holding `marker` ("images", "transforms.json"), sorted;
// the dataset's own folders (config/, preview/, paper_textures/) are no objects. Throws
// InputError when `root` is no folder or holds no such variant.
std::vector<std::filesystem::path> variant_folders(const std::filesystem::path& root, const std::string& marker);

}  // namespace make_dataset
