#pragma once
// Image textures: RGBA texels in scene-linear or non-colour data (kept as bytes for 8-bit images
// whose colour is not premultiplied here, as floats otherwise), sampled bilinearly like
// Cycles' "Linear" interpolation (texel centres at (i + 0.5) / W). Given a footprint (the width
// in UV units a ray cone covers), trilinearly from a mip pyramid of 2 x 2 box-filtered levels,
// each made the first time a lookup needs it (Cycles 3.4 on the CPU has no mipmaps; the
// renderer asks for footprints only when RenderSettings::mipmaps is on). Every level is an entry
// of the bounded texture cache (matrender/texture_cache.h).
//
// Alpha, as Blender 3.4 treats an image of alpha mode Straight (its default): an 8- or 16-bit
// sRGB image with an alpha channel is premultiplied by its alpha when loaded (on the encoded
// values) and filtered so, which keeps the colour of fully transparent texels out of their
// neighbours. Its colour comes back premultiplied, unless the material takes its alpha from the
// same image (Blender: the Alpha output is linked), when it is divided by the filtered alpha
// again. Non-colour (data) images keep their channels as stored: channel-packed maps.
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "matmaterial/material_parameters.h"
#include "matmaterial/texture_transform.h"

namespace matrender {

using matmaterial::ColorSpace;
using matmaterial::TextureWrap;

struct TexelLevel;
class TexelPage;

class Texture {
 public:
  ~Texture();
  // Loads any format OpenImageIO reads (PNG, JPEG, EXR, TIFF, ...). Throws std::runtime_error
  // naming the path and the problem. A path with the token <UDIM> names a UDIM set: the files
  // with a four-digit tile number there (name.1001.png, name.1002.png, ...), tile 1001 + floor(u)
  // + 10 floor(v) covering [floor(u), floor(u) + 1) x [floor(v), floor(v) + 1), as Blender's UDIM
  // images and the UV pass's tiles; every tile's header is read here, its pixels when a lookup
  // first lands in it. The tile is Cycles 3.4's (svm_node_tex_image): u and v truncated toward
  // zero, so (-1, 0) still reads tile 1001's first column or row, wrapped; UVs in a tile the set
  // lacks, or left of u = -1 or beyond u = 10, read Cycles' missing-texture magenta (1, 0, 1, 1).
  static std::shared_ptr<const Texture> load(const std::string& path, ColorSpace space,
                                             TextureWrap wrap = TextureWrap::Repeat);
  // An environment map: load() of one image whose negative components are told apart, the
  // small ones lossy compression leaves clamped to 0 and a deeper one refused naming its texel
  // (src/texture/negative_radiance.h).
  static std::shared_ptr<const Texture> load_radiance(const std::string& path, ColorSpace space);
  // From 8-bit pixels in memory, rows top to bottom.
  static std::shared_ptr<const Texture> from_pixels8(int width, int height, int channels,
                                                     const uint8_t* pixels, ColorSpace space,
                                                     TextureWrap wrap = TextureWrap::Repeat,
                                                     std::string name = "<memory>");
  // From float pixels (already linear), rows top to bottom.
  static std::shared_ptr<const Texture> from_pixelsf(int width, int height, int channels,
                                                     const float* pixels, ColorSpace space,
                                                     TextureWrap wrap = TextureWrap::Repeat,
                                                     std::string name = "<memory>");

  // Bilinear lookup at (u, v), v = 0 at the bottom row (OpenGL/Blender UV convention).
  // Returns linear RGBA: sRGB textures are interpolated on the encoded values and converted
  // afterwards, as Cycles does for 8-bit images. `unassociate`: divide a premultiplied colour by
  // the alpha again (the material uses this image's alpha).
  // footprint: the lookup's width in UV units; at or below one texel, the plain bilinear lookup.
  glm::vec4 sample(glm::vec2 uv, bool unassociate = false, float footprint = 0.0f) const;
  // Stored premultiplied by alpha (the Straight images above).
  bool associated_alpha() const { return associated_alpha_; }
  // A UDIM set: its tile numbers, and how many of them have been loaded so far.
  std::vector<int> udim_tiles() const;
  size_t loaded_udim_tiles() const;

  int width() const { return width_; }
  int height() const { return height_; }
  const std::string& name() const { return name_; }
  ColorSpace color_space() const { return space_; }

 private:
  Texture() = default;
  // What decoding gives: level 0 and how its lookups finish.
  struct Decoded;
  static Decoded decode_floats(int width, int height, int channels, const float* pixels, const std::string& name);
  static Decoded decode_bytes(int width, int height, int channels, const uint8_t* pixels, ColorSpace space,
                              const std::string& name);
  static Decoded decode_file(const std::string& path, ColorSpace space);
  // One image file's texture, its level 0 passed through `adjust` (when given) at every decoding.
  static std::shared_ptr<const Texture> load_file(const std::string& path, ColorSpace space, TextureWrap wrap,
                                                  void (*adjust)(TexelLevel&, const std::string&));
  static void associate_alpha(Decoded& decoded);
  // A texture of these texels. `remake`, when given, makes level 0 again after the texture
  // cache dropped it; without it level 0 stays in memory.
  static std::shared_ptr<const Texture> with_texels(Decoded decoded, ColorSpace space, TextureWrap wrap, std::string name,
                                                    std::function<TexelLevel()> remake);

  glm::vec4 bilinear(const TexelLevel& level, glm::vec2 uv) const;
  // A level's texels, pinned by this thread (texel_cache.h): made the first time a lookup needs
  // them, or again after the cache dropped them.
  const TexelLevel& texels(size_t level) const;
  int width_ = 0;
  int height_ = 0;
  ColorSpace space_ = ColorSpace::SRGB;
  TextureWrap wrap_ = TextureWrap::Repeat;
  bool convert_srgb_after_filtering_ = false;
  bool associated_alpha_ = false;
  std::string name_;
  // The mip pyramid, level 0 first, each level an entry of the texture cache.
  std::vector<std::unique_ptr<TexelPage>> levels_;
  struct UdimTile {
    int number;
    std::string path;
    int width, height;  // from the header read at load
    std::once_flag loaded;
    std::shared_ptr<const Texture> texture;  // set once, by the first lookup in the tile
  };
  std::vector<std::unique_ptr<UdimTile>> udim_;  // by tile number; empty for a single image
  static std::shared_ptr<const Texture> load_udim(const std::string& pattern, ColorSpace space, TextureWrap wrap);
  glm::vec4 sample_udim(glm::vec2 uv, bool unassociate, float footprint) const;
};

using TexturePtr = std::shared_ptr<const Texture>;

// The colour space Blender gives an image file it loads: scene-linear for float data (EXR, HDR,
// float TIFF), which is then not converted (NonColor), and sRGB for 8- and 16-bit integer data.
// Reads only the file's header; throws std::runtime_error naming the path when it cannot.
ColorSpace blender_default_color_space(const std::string& path);

}  // namespace matrender
