#pragma once
// Real files for the reader and writer tests: bytes in and out, and PNG images encoded here,
// independently of the libraries under test (zlib "stored" blocks need no compressor).
#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

inline void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  REQUIRE(out.good());
}

inline void write_bytes(const std::string& path, const std::vector<uint8_t>& bytes) {
  write_bytes(path, std::string(bytes.begin(), bytes.end()));
}

inline void write_text(const std::string& path, const std::string& text) { write_bytes(path, text); }

inline std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

namespace png_detail {

inline uint32_t crc32(const std::vector<uint8_t>& bytes) {
  uint32_t crc = 0xFFFFFFFFu;
  for (const uint8_t byte : bytes) {
    crc ^= byte;
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

inline void append_be32(std::vector<uint8_t>& out, uint32_t value) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<uint8_t>(value >> shift));
}

inline void append_chunk(std::vector<uint8_t>& png, const char* type, const std::vector<uint8_t>& data) {
  append_be32(png, static_cast<uint32_t>(data.size()));
  std::vector<uint8_t> typed(type, type + 4);
  typed.insert(typed.end(), data.begin(), data.end());
  png.insert(png.end(), typed.begin(), typed.end());
  append_be32(png, crc32(typed));
}

}  // namespace png_detail

// Grey, grey-alpha, RGB or RGBA (channels 1 to 4) PNG of `bits` 8 or 16, samples row by row from
// the top.
inline std::vector<uint8_t> encode_png(int width, int height, int channels, int bits,
                                       const std::vector<uint16_t>& samples) {
  using namespace png_detail;
  const size_t row = static_cast<size_t>(width) * static_cast<size_t>(channels);
  std::vector<uint8_t> raw;
  for (size_t y = 0; y < static_cast<size_t>(height); ++y) {
    raw.push_back(0);  // filter: none
    for (size_t s = 0; s < row; ++s) {
      const uint16_t value = samples[y * row + s];
      if (bits == 16) raw.push_back(static_cast<uint8_t>(value >> 8));
      raw.push_back(static_cast<uint8_t>(value & 0xFF));
    }
  }
  REQUIRE(raw.size() < 65536);  // one stored block
  const uint16_t length = static_cast<uint16_t>(raw.size());
  // zlib header, then a final stored block: length and its complement, little-endian.
  std::vector<uint8_t> zlib = {0x78, 0x01, 0x01};
  for (const uint16_t value : {length, static_cast<uint16_t>(~length)})
    zlib.insert(zlib.end(), {static_cast<uint8_t>(value & 0xFF), static_cast<uint8_t>(value >> 8)});
  zlib.insert(zlib.end(), raw.begin(), raw.end());
  uint32_t a = 1, b = 0;  // Adler-32
  for (const uint8_t byte : raw) {
    a = (a + byte) % 65521;
    b = (b + a) % 65521;
  }
  append_be32(zlib, (b << 16) | a);

  std::vector<uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  std::vector<uint8_t> header;
  append_be32(header, static_cast<uint32_t>(width));
  append_be32(header, static_cast<uint32_t>(height));
  const uint8_t colour_type = channels == 1 ? 0 : channels == 2 ? 4 : channels == 3 ? 2 : 6;
  header.insert(header.end(), {static_cast<uint8_t>(bits), colour_type, 0, 0, 0});
  append_chunk(png, "IHDR", header);
  append_chunk(png, "IDAT", zlib);
  append_chunk(png, "IEND", {});
  return png;
}

// 8-bit grey or RGB PNG.
inline std::vector<uint8_t> encode_png(int width, int height, int channels, const std::vector<uint8_t>& pixels) {
  return encode_png(width, height, channels, 8, std::vector<uint16_t>(pixels.begin(), pixels.end()));
}
