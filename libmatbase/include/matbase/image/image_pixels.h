#pragma once
// Decoded 8-bit images as every reader and writer passes them: the mesh readers' textures, a
// material folder's maps, the encoders' input.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace matbase {

// Decoded 8-bit image, rows top to bottom, channels interleaved (1..4).
struct ImagePixels {
  std::string name;  // file name or "<file>#image<k>" for embedded images
  int width = 0;
  int height = 0;
  int channels = 0;
  std::vector<uint8_t> data;
};

// A width x height image of `channels` channels, every byte 0, for a rasteriser to fill.
ImagePixels blank_image(std::string name, int width, int height, int channels);

// Positive size, 1 to 4 channels, and exactly width x height x channels bytes.
bool is_well_formed(const ImagePixels& image);

// The value channel `channel` (0 R, 1 G, 2 B, 3 A) of texel `texel` reads as, the way the renderer
// expands images to RGBA: a grey image (1 channel, or 2 with alpha) gives its grey for R, G and
// B; an image without alpha reads 255 for A.
uint8_t texel_channel(const ImagePixels& image, size_t texel, int channel);

}  // namespace matbase
