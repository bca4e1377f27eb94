#include "image_file.h"

#include <cstddef>
#include <limits>

#include <tiny_gltf.h>

#include "image_bytes.h"
#include "matgeom/input_file.h"
#include "matgeom/text.h"

namespace matgeom {

// tinygltf's exported decoder always expands to RGBA (the channel-preserving option is internal
// to its implementation), so every image read here has 4 channels.
std::optional<std::string> decode_image_file(const std::filesystem::path& file, const std::string& name,
                                             ImagePixels& out) {
  std::string bytes;
  if (std::optional<std::string> problem = read_whole_file(file, bytes)) return problem;
  if (bytes.size() > static_cast<size_t>(std::numeric_limits<int>::max())) return std::string("the image is too large");
  tinygltf::Image image;
  image.name = file.string();
  std::string errors;
  std::string warnings;
  const bool decoded = tinygltf::LoadImageData(&image, 0, &errors, &warnings, 0, 0,
                                               reinterpret_cast<const unsigned char*>(bytes.data()),
                                               static_cast<int>(bytes.size()), nullptr);
  const size_t expected = static_cast<size_t>(image.width) * static_cast<size_t>(image.height) *
                          static_cast<size_t>(image.component) * static_cast<size_t>(image.bits / 8);
  if (!decoded || image.component != 4 || (image.bits != 8 && image.bits != 16) || image.image.size() != expected)
    return "cannot decode the image (" + trim(errors) + ")";
  out.name = name;
  out.width = image.width;
  out.height = image.height;
  out.channels = image.component;
  out.data = to_8_bit(image);
  return std::nullopt;
}

}  // namespace matgeom
