#pragma once
// Where the image an MTL map statement names is: the path as written often comes from another
// machine ("C:\Users\me\textures\wall.jpg", ".\textures\wall.jpg"), so the places Blender 3.4's
// importer tries are tried in its order (obj_import_mtl.cc, load_texture_image), and then the
// MTL's subfolders, where such exports usually keep their textures.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace matgeom::obj {

struct TexturePathSearch {
  std::optional<std::filesystem::path> found;
  std::vector<std::string> tried;  // the places looked at, for a message when none holds the file
};

// Tries, with backslashes read as folder separators and quotes dropped: the MTL's folder joined
// with the path; the path itself when it is absolute; the first with underscores as blanks;
// the file name alone in the MTL's folder; then the file name in the MTL's subfolders (up to
// kMaxSubfolderDepth deep and kMaxSubfoldersSearched folders, the first in sorted order, level by
// level: an OBJ left in a home folder must not set off a walk of the whole disk).
TexturePathSearch find_texture_file(const std::filesystem::path& mtl_folder, const std::string& written);

constexpr int kMaxSubfolderDepth = 3;
constexpr size_t kMaxSubfoldersSearched = 1000;

}  // namespace matgeom::obj
