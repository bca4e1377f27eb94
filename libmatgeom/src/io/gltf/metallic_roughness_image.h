#pragma once
// glTF keeps roughness and metallic in one image: roughness = roughnessFactor x G, metallic =
// metallicFactor x B (glTF 2.0, 3.9.2). A MaterialInputs may read them from any channel of any
// image; this finds or makes the one image glTF needs.
#include <optional>
#include <string>
#include <vector>

#include "matgeom/object_asset.h"

namespace matgeom::gltf {

struct MetallicRoughnessImage {
  int image = -1;                     // an asset image already in glTF's layout, -1 for none
  std::optional<matbase::ImagePixels> packed;  // or a new one, when no asset image is
};

// An asset image serves as it is when both inputs read it at glTF's channels, or when one input
// does and the other is a constant over a channel that is 255 everywhere (a factor of 1).
// Otherwise G and B are copied from the inputs' channels (nearest texel where the two images
// differ in size, at the larger size) and a constant's channel is 255. `what` names the material
// in errors (an image index out of range, a channel the image lacks).
MetallicRoughnessImage metallic_roughness_image(const matmaterial::MaterialInputs& material, const std::vector<matbase::ImagePixels>& images,
                                                const std::string& what);

}  // namespace matgeom::gltf
