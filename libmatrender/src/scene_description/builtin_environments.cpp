#include "matrender/builtin_environments.h"

#include <algorithm>
#include <filesystem>

#include "matbase/input_error.h"

namespace matrender {

const std::vector<std::string>& builtin_environment_names() {
  static const std::vector<std::string> names = {"city",  "courtyard", "forest",  "interior",
                                                 "night", "studio",    "sunrise", "sunset"};
  return names;
}

bool is_builtin_environment(const std::string& text) {
  const std::vector<std::string>& names = builtin_environment_names();
  return std::find(names.begin(), names.end(), text) != names.end();
}

std::string builtin_environment_path(const std::string& name, const std::string& folder) {
  const std::filesystem::path path = std::filesystem::path(folder) / (name + ".exr");
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
    throw matbase::InputError("the built-in environment \"" + name + "\" is not in " + folder +
                              " (Debian's blender-data package puts it there: apt-get install blender-data, or "
                              "bash scripts/install_deps.sh)");
  return path.string();
}

}  // namespace matrender
