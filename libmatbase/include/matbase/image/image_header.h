#pragma once
// What an image file's header declares, held against what the file can hold before anything is
// allocated for it. A PNG's pixels are deflate data, and deflate inflates at most 1032-fold (a
// 258-byte match coded in 2 bits): a 1 MB file cannot hold 60000 x 60000 pixels (3.6 GB), so a
// header that says so is damaged or hostile, whatever the machine's memory would allow.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace matbase {

// What a PNG's IHDR chunk declares.
struct PngHeader {
  uint32_t width = 0, height = 0;
  int bit_depth = 0;   // 1, 2, 4, 8 or 16
  int channels = 0;    // samples per pixel: 1 (grey, palette index), 2, 3 or 4
};

// The header of PNG bytes (their first 33 are enough), or nothing when they are not a PNG.
std::optional<PngHeader> png_header(std::string_view bytes);

// Nothing when `bytes` (an image file's first bytes; its size `file_bytes`) are no PNG or a PNG
// whose pixels could be in that many bytes, else "declares 60000 x 60000 pixels, 3.4 GiB of
// image data, more than the 1032-fold of its 1.0 MiB that a PNG can inflate to: the file is
// damaged or not what it claims".
std::optional<std::string> png_declared_size_problem(std::string_view bytes, uint64_t file_bytes);

// The same for the file at `path`; nothing too when it cannot be read (its reader says why).
std::optional<std::string> declared_size_problem(const std::filesystem::path& path);

}  // namespace matbase
