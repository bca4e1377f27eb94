#pragma once
// PNG encoding of the images write_obj writes beside the .obj.
#include <string>

#include "matgeom/object_asset.h"

namespace matgeom::obj {

// PNG bytes from tinygltf's stb_image_write, captured by a WriteWholeFile callback instead of
// written, so that the file is staged like the others.
std::string encode_png(const ImagePixels& pixels, const std::string& path);

}  // namespace matgeom::obj
