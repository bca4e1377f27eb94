#include "dataset_folders.h"

#include <algorithm>

#include "dataset_config.h"

namespace make_dataset {

std::vector<std::filesystem::path> variant_folders(const std::filesystem::path& root, const std::string& marker) {
  namespace fs = std::filesystem;
  if (!fs::is_directory(root)) throw InputError(root.string() + ": no such folder");
  std::vector<fs::path> variants;
  for (const fs::directory_entry& object : fs::directory_iterator(root)) {
    const std::string name = object.path().filename().string();
    if (!object.is_directory() || name == "config" || name == "preview" || name == "paper_textures") continue;
    for (const fs::directory_entry& variant : fs::directory_iterator(object.path()))
      if (variant.is_directory() && fs::exists(variant.path() / marker)) variants.push_back(variant.path());
  }
  if (variants.empty())
    throw InputError(root.string() + ": holds no <object>/<variant>/" + marker + ": not a dataset");
  std::sort(variants.begin(), variants.end());
  return variants;
}

}  // namespace make_dataset
