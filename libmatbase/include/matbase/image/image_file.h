#pragma once
// Image files as the readers of meshes and material folders keep them: decoded with tinygltf's
// stb_image (PNG, JPEG, BMP, TGA) into 8-bit RGBA.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "matbase/image/image_pixels.h"

namespace matbase {

// Decodes `file` into `out` (4 channels; 16-bit channels rounded to 8 bits), named `name`; or
// returns the problem ("no such file", "cannot decode the image: ...", ...).
std::optional<std::string> decode_image_file(const std::filesystem::path& file, const std::string& name,
                                             ImagePixels& out);

// The format of encoded image bytes, from their signature, when stb_image must not be given them:
// a float format (OpenEXR, Radiance HDR: it would tone-map the values to 8 bits) or one it cannot
// read (TIFF, WebP, KTX, DDS, JPEG 2000, AVIF/HEIF). Stated as a problem: "an OpenEXR image;
// images are read from PNG, JPEG, BMP or TGA files".
std::optional<std::string> unread_image_format(std::string_view bytes);

// Why stb_image failed on `bytes`, in our words: the damaged or truncated data of the format their
// signature names, or none of the formats read here.
std::string undecodable_image(std::string_view bytes);

// What Blender makes of a data (Non-Color) image's colour fed to a float socket, as a
// roughness or metallic map is: its luminance, with the Rec. 709 weights of Blender's default
// colour management, of texel `pixel` of an RGBA image.
inline uint8_t data_luminance(const ImagePixels& rgba, size_t pixel) {
  const uint8_t* p = &rgba.data[4 * pixel];
  return static_cast<uint8_t>((2126u * p[0] + 7152u * p[1] + 722u * p[2] + 5000u) / 10000u);
}

}  // namespace matbase
