#include "matdataset/format/dataset_folders.h"

#include <algorithm>

#include <fmt/format.h>

#include "matbase/input_error.h"

namespace matdataset {

namespace {

// Linux allows any byte but '/' and NUL; a dataset is also copied to Windows shares and archives.
constexpr const char* kUnportableCharacters = "/\\<>:\"|?*";
// NAME_MAX of Linux's file systems and of NTFS (in bytes here, the stricter reading).
constexpr size_t kMaxNameBytes = 255;

bool is_dataset_own_entry(const std::string& name) {
  for (const char* own : {kConfigFolder, kPreviewFolder, kPaperTexturesFolder, kSegmentationMapFile})
    if (name == own) return true;
  return false;
}

}  // namespace

std::optional<std::string> object_folder_problem(const std::string& name) {
  if (name.empty()) return "it is empty";
  if (name.size() > kMaxNameBytes)
    return fmt::format("it is {} bytes long, more than the {} a file name may have", name.size(), kMaxNameBytes);
  if (const size_t at = name.find_first_of(kUnportableCharacters); at != std::string::npos)
    return fmt::format("'{}' is not allowed in a folder name (nor any of {})", name[at], kUnportableCharacters);
  if (std::any_of(name.begin(), name.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; }))
    return "it holds a control character";
  if (name[0] == '.') return "a name starting with '.' is hidden (or is . or ..)";
  if (name.rfind("_tmp", 0) == 0) return "dataset readers skip folders starting with _tmp (the MatPredict layout's scratch folders)";
  if (is_dataset_own_entry(name)) return "the dataset keeps its own " + name + " there";
  return std::nullopt;
}

std::vector<std::filesystem::path> variant_folders(const std::filesystem::path& root, const std::string& marker) {
  namespace fs = std::filesystem;
  if (!fs::is_directory(root)) throw matbase::InputError(root.string() + ": no such folder");
  std::vector<fs::path> variants;
  for (const fs::directory_entry& object : fs::directory_iterator(root)) {
    const std::string name = object.path().filename().string();
    if (!object.is_directory() || is_dataset_own_entry(name)) continue;
    for (const fs::directory_entry& variant : fs::directory_iterator(object.path()))
      if (variant.is_directory() && fs::exists(variant.path() / marker)) variants.push_back(variant.path());
  }
  if (variants.empty())
    throw matbase::InputError(root.string() + ": holds no <object>/<variant>/" + marker + ": not a dataset");
  std::sort(variants.begin(), variants.end());
  return variants;
}

}  // namespace matdataset
