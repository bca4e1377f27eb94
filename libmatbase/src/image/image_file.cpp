#include "matbase/image/image_file.h"

#include <cstddef>
#include <limits>
#include <string_view>
#include <utility>

#include <tiny_gltf.h>

#include "matbase/file/file_error.h"
#include "matbase/file/input_file.h"
#include "matbase/image/image_header.h"
#include "matbase/image/unorm.h"

namespace matbase {

namespace {

constexpr const char* kReadFormats = "images are read from PNG, JPEG, BMP or TGA files";

// Whether `signature` stands at `offset` of `bytes`; false when they end before it.
bool has_at(std::string_view bytes, size_t offset, std::string_view signature) {
  return offset <= bytes.size() && bytes.substr(offset, signature.size()) == signature;
}

bool starts_with(std::string_view bytes, std::string_view signature) { return has_at(bytes, 0, signature); }

// The formats stb_image decodes that carry a signature (TGA has none).
const char* decodable_format(std::string_view bytes) {
  if (starts_with(bytes, "\x89PNG\r\n\x1a\n")) return "PNG";
  if (starts_with(bytes, "\xFF\xD8\xFF")) return "JPEG";
  if (starts_with(bytes, "BM")) return "BMP";
  if (starts_with(bytes, "GIF8")) return "GIF";
  return nullptr;
}

}  // namespace

std::optional<std::string> unread_image_format(std::string_view bytes) {
  static const std::pair<std::string_view, const char*> kSignatures[] = {
      {"\x76\x2F\x31\x01", "an OpenEXR image"},
      {"#?RADIANCE", "a Radiance HDR image"},
      {"#?RGBE", "a Radiance HDR image"},
      {std::string_view("II*\0", 4), "a TIFF image"},
      {std::string_view("MM\0*", 4), "a TIFF image"},
      {"\xABKTX", "a KTX texture"},
      {"DDS ", "a DDS texture"},
      {std::string_view("\0\0\0\x0CjP  ", 8), "a JPEG 2000 image"},
  };
  for (const auto& [signature, format] : kSignatures)
    if (starts_with(bytes, signature)) return std::string(format) + "; " + kReadFormats;
  if (starts_with(bytes, "RIFF") && has_at(bytes, 8, "WEBP")) return std::string("a WebP image; ") + kReadFormats;
  if (has_at(bytes, 4, "ftyp")) return std::string("an AVIF or HEIF image; ") + kReadFormats;
  return std::nullopt;
}

std::string undecodable_image(std::string_view bytes) {
  if (const char* format = decodable_format(bytes)) return concat("the ", format, " data is damaged or cut short");
  return std::string("not an image in a format read here (") + kReadFormats + ")";
}

// tinygltf's exported decoder always expands to RGBA (the channel-preserving option is internal
// to its implementation), so every image read here has 4 channels.
std::optional<std::string> decode_image_file(const std::filesystem::path& file, const std::string& name,
                                             ImagePixels& out) {
  std::string bytes;
  if (std::optional<std::string> problem = read_whole_file(file, bytes)) return problem;
  if (bytes.size() > static_cast<size_t>(std::numeric_limits<int>::max())) return std::string("the image is too large");
  if (std::optional<std::string> format = unread_image_format(bytes)) return "cannot decode the image: " + *format;
  if (std::optional<std::string> problem = png_declared_size_problem(bytes, bytes.size())) return *problem;
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
    return "cannot decode the image: " + undecodable_image(bytes);
  out.name = name;
  out.width = image.width;
  out.height = image.height;
  out.channels = image.component;
  out.data = unorm_channels_to_8_bit(image.image, image.bits);
  return std::nullopt;
}

}  // namespace matbase
