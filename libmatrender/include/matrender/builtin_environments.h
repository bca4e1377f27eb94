#pragma once
// Eight real HDR environments that need no download: the CC0 equirectangular images from Poly Haven
// (1024 x 512, linear RGB EXR) that Debian's blender-data package ships for Blender's studio
// lights. The package holds data only (it depends on python3 alone); matpredict never runs Blender.
// A scene file's "environment" and render_object --environment take their names.
#include <optional>
#include <string>
#include <vector>

namespace matrender {

// Where Debian's blender-data puts them.
constexpr const char* kBuiltinEnvironmentFolder = "/usr/share/blender/datafiles/studiolights/world";

// city, courtyard, forest, interior, night, studio, sunrise, sunset.
const std::vector<std::string>& builtin_environment_names();

// Whether `text` names a built-in environment (one of the names as written: a file has an extension).
bool is_builtin_environment(const std::string& text);

// The file of built-in environment `name` in `folder`; matbase::InputError naming the folder
// searched and the package that fills it when the file is not there.
std::string builtin_environment_path(const std::string& name, const std::string& folder = kBuiltinEnvironmentFolder);

}  // namespace matrender
