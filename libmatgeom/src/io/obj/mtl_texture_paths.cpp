#include "io/obj/mtl_texture_paths.h"

#include <algorithm>

#include "matbase/file/input_file.h"
#include <system_error>

namespace matgeom::obj {
namespace {

namespace fs = std::filesystem;

bool is_file(const fs::path& path) { return !matbase::input_file_problem(path.string()); }

// The first file named `name` under `folder`, searched breadth first in sorted order, `depth`
// levels of subfolders deep; unreadable folders are passed over.
std::optional<fs::path> file_in_subfolders(const fs::path& folder, const fs::path& name, int depth) {
  std::vector<fs::path> level = {folder};
  size_t searched = 0;
  for (int d = 0; d < depth && !level.empty(); ++d) {
    std::vector<fs::path> next;
    for (const fs::path& parent : level) {
      if (++searched > kMaxSubfoldersSearched) return std::nullopt;
      std::error_code error;
      std::vector<fs::path> children;
      for (fs::directory_iterator it(parent, error), end; !error && it != end; it.increment(error))
        if (it->is_directory(error)) children.push_back(it->path());
      std::sort(children.begin(), children.end());
      for (const fs::path& child : children)
        if (is_file(child / name)) return child / name;
      next.insert(next.end(), children.begin(), children.end());
    }
    level = std::move(next);
  }
  return std::nullopt;
}

}  // namespace

TexturePathSearch find_texture_file(const fs::path& mtl_folder, const std::string& written) {
  std::string path = written;
  path.erase(std::remove(path.begin(), path.end(), '"'), path.end());
  std::replace(path.begin(), path.end(), '\\', '/');
  std::string spaced = path;
  std::replace(spaced.begin(), spaced.end(), '_', ' ');
  const fs::path file_name = fs::path(path).filename();

  TexturePathSearch search;
  std::vector<fs::path> candidates = {mtl_folder / path};
  if (fs::path(path).is_absolute()) candidates.emplace_back(path);
  if (spaced != path) candidates.push_back(mtl_folder / spaced);
  if (!file_name.empty()) candidates.push_back(mtl_folder / file_name);
  for (const fs::path& candidate : candidates) {
    if (std::find(search.tried.begin(), search.tried.end(), candidate.string()) != search.tried.end()) continue;
    search.tried.push_back(candidate.string());
    if (is_file(candidate)) {
      search.found = candidate;
      return search;
    }
  }
  if (file_name.empty()) return search;
  search.tried.push_back((mtl_folder / "*" / file_name).string() + " (subfolders)");
  search.found = file_in_subfolders(mtl_folder, file_name, kMaxSubfolderDepth);
  return search;
}

}  // namespace matgeom::obj
