#pragma once
// 8-bit PNG encoding in memory, so that the bytes go through the checked, atomic writers
// (matbase/file/atomic_file.h): the OBJ writer's textures, evaluation panels.
#include <string>

#include "matbase/image/image_pixels.h"

namespace matbase {

// PNG bytes from tinygltf's stb_image_write, captured by a WriteWholeFile callback instead of
// written. `path` names the image in errors.
std::string encode_png(const ImagePixels& pixels, const std::string& path);

}  // namespace matbase
