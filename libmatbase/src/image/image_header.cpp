#include "matbase/image/image_header.h"

#include <cmath>
#include <fstream>

#include "matbase/memory_limit.h"

namespace matbase {
namespace {

// PNG, section 5.2 (signature) and 11.2.2 (IHDR: width, height, bit depth, colour type, ...).
constexpr std::string_view kPngSignature("\x89PNG\r\n\x1a\n", 8);
constexpr size_t kIhdrEnd = 8 + 8 + 13;  // signature, chunk length and type, IHDR's fields
// Deflate's largest ratio: a 258-byte match is the shortest code pair, 2 bits (RFC 1951, 3.2.5).
constexpr int kMostInflation = 1032;

uint32_t big_endian(std::string_view bytes, size_t at) {
  uint32_t value = 0;
  for (size_t k = 0; k < 4; ++k) value = (value << 8) | static_cast<uint8_t>(bytes[at + k]);
  return value;
}

// Samples per pixel of a PNG colour type (table 11.1); 0 for none.
int png_channels(int colour_type) {
  switch (colour_type) {
    case 0: return 1;  // grey
    case 2: return 3;  // RGB
    case 3: return 1;  // palette index
    case 4: return 2;  // grey and alpha
    case 6: return 4;  // RGBA
    default: return 0;
  }
}

}  // namespace

std::optional<PngHeader> png_header(std::string_view bytes) {
  if (bytes.size() < kIhdrEnd || bytes.substr(0, 8) != kPngSignature || bytes.substr(12, 4) != "IHDR")
    return std::nullopt;
  PngHeader header;
  header.width = big_endian(bytes, 16);
  header.height = big_endian(bytes, 20);
  header.bit_depth = static_cast<uint8_t>(bytes[24]);
  header.channels = png_channels(static_cast<uint8_t>(bytes[25]));
  return header;
}

std::optional<std::string> png_declared_size_problem(std::string_view bytes, uint64_t file_bytes) {
  const std::optional<PngHeader> header = png_header(bytes);
  if (!header || header->channels == 0) return std::nullopt;  // the decoder names a bad colour type
  // The filtered scanlines deflate encodes: a filter byte and the row's packed samples (without
  // interlacing, which only adds filter bytes).
  const double row_bytes =
      1.0 + std::ceil(static_cast<double>(header->width) * header->channels * header->bit_depth / 8.0);
  const double image_bytes = row_bytes * static_cast<double>(header->height);
  if (image_bytes <= kMostInflation * static_cast<double>(file_bytes)) return std::nullopt;
  return "declares " + std::to_string(header->width) + " x " + std::to_string(header->height) + " pixels, " +
         byte_size_text(image_bytes) + " of image data, more than the " + std::to_string(kMostInflation) + "-fold of its " +
         byte_size_text(static_cast<double>(file_bytes)) +
         " that a PNG can inflate to: the file is damaged or not what it claims";
}

std::optional<std::string> declared_size_problem(const std::filesystem::path& path) {
  std::error_code error;
  const uint64_t size = std::filesystem::file_size(path, error);
  if (error) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  std::string first(kIhdrEnd, '\0');
  if (!in.read(first.data(), static_cast<std::streamsize>(first.size()))) return std::nullopt;
  return png_declared_size_problem(first, size);
}

}  // namespace matbase
