#pragma once
// 8-bit PNG encoding in memory, so that the bytes go through the checked, atomic writers
// (matgeom/atomic_file.h): the OBJ writer's textures, evaluation panels.
#include <string>

#include "matgeom/object_asset.h"

namespace matgeom {

// PNG bytes from tinygltf's stb_image_write, captured by a WriteWholeFile callback instead of
// written. `path` names the image in errors.
std::string encode_png(const ImagePixels& pixels, const std::string& path);

}  // namespace matgeom
