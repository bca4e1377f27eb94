#pragma once
// Image files as the readers of meshes and material folders keep them: decoded with tinygltf's
// stb_image (PNG, JPEG, BMP, TGA) into 8-bit RGBA.
#include <filesystem>
#include <optional>
#include <string>

#include "matgeom/object_asset.h"

namespace matgeom {

// Decodes `file` into `out` (4 channels; 16-bit channels rounded to 8 bits), named `name`; or
// returns the problem ("no such file", "cannot decode the image (...)", ...).
std::optional<std::string> decode_image_file(const std::filesystem::path& file, const std::string& name,
                                             ImagePixels& out);

}  // namespace matgeom
