#include "matbase/file/output_folder.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace matbase {

std::optional<std::string> output_folder_problem(const std::string& folder) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::path absolute = fs::absolute(folder, error);
  // The folder itself, or the nearest of its parents that exists.
  fs::path nearest = absolute;
  while (!fs::exists(nearest, error) && nearest.has_relative_path()) nearest = nearest.parent_path();
  if (!fs::is_directory(nearest, error))
    return nearest == absolute ? folder + " is a file, not a folder"
                               : folder + ": " + nearest.string() + " is a file, so no folder can be made in it";
  if (::access(nearest.c_str(), W_OK | X_OK) != 0)
    return folder + ": " + nearest.string() + " is not writable (" + std::strerror(errno) + ")";
  return std::nullopt;
}

}  // namespace matbase
