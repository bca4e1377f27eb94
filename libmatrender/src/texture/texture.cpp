#include "matrender/texture.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <optional>
#include <stdexcept>

#include <emmintrin.h>

#include <OpenImageIO/imageio.h>

#include "matbase/file/input_file.h"
#include "matbase/image/image_header.h"
#include "matbase/image/srgb.h"
#include "matbase/memory_limit.h"
#include "matbase/stderr_capture.h"
#include "matbase/text.h"
#include "texture/negative_radiance.h"
#include "texture/texel_cache.h"
#include "texture/texel_level.h"

namespace matrender {
namespace {

namespace fs = std::filesystem;

const std::string kUdimToken = "<UDIM>";

// Expands 1..4 interleaved channels to RGBA (grey to RGB, alpha 1 when absent).
glm::vec4 to_rgba(const float* p, int channels) {
  switch (channels) {
    case 1: return {p[0], p[0], p[0], 1.0f};
    case 2: return {p[0], p[0], p[0], p[1]};
    case 3: return {p[0], p[1], p[2], 1.0f};
    default: return {p[0], p[1], p[2], p[3]};
  }
}

// Refuses, before anything is allocated, a texture whose texels (`texel_bytes` each: RGBA floats
// or bytes) and the `staging_bytes_per_texel` of its decoding do not fit in memory.
void require_texture_memory(const std::string& name, int width, int height, double staging_bytes_per_texel,
                            double texel_bytes = sizeof(glm::vec4)) {
  const double texels = static_cast<double>(width) * static_cast<double>(height);
  matbase::require_memory(texels * (texel_bytes + staging_bytes_per_texel),
                          "its " + std::to_string(width) + " x " + std::to_string(height) + " texels", name);
}

// Refuses a file whose header declares more pixels than its bytes can hold, before the decoder
// allocates for them (matbase/image/image_header.h).
void require_plausible_header(const std::string& path) {
  if (const std::optional<std::string> problem = matbase::declared_size_problem(path))
    throw std::runtime_error(path + ": " + *problem);
}

int wrap_index(int i, int n, TextureWrap wrap) {
  if (wrap == TextureWrap::Clamp) return i < 0 ? 0 : (i >= n ? n - 1 : i);
  const int r = i % n;
  return r < 0 ? r + n : r;
}

// Texel (x, y) of `level` as four floats in one register: bytes over 255 (level.texel's value,
// exactly), or the stored floats.
template <bool kBytes>
__m128 texel_lanes(const TexelLevel& level, int x, int y) {
  const size_t i = static_cast<size_t>(y) * static_cast<size_t>(level.width) + static_cast<size_t>(x);
  if constexpr (!kBytes) {
    return _mm_loadu_ps(&level.floats[i].x);
  } else {
    uint32_t rgba;
    std::memcpy(&rgba, level.bytes.data() + 4 * i, sizeof(rgba));
    const __m128i zero = _mm_setzero_si128();
    const __m128i words = _mm_unpacklo_epi16(_mm_unpacklo_epi8(_mm_cvtsi32_si128(static_cast<int>(rgba)), zero), zero);
    return _mm_mul_ps(_mm_cvtepi32_ps(words), _mm_set1_ps(1.0f / 255.0f));
  }
}

// (1 - ty) ((1 - tx) t00 + tx t10) + ty ((1 - tx) t01 + tx t11) over the four channels at once
// (SSE2, in every x86-64): the same operations in the same order as per channel, so the same
// floats. One channel at a time a lookup took 294 instructions on the textured vase, now 213.
template <bool kBytes>
glm::vec4 blend_texels(const TexelLevel& level, int x0, int x1, int y0, int y1, float tx, float ty) {
  const __m128 left = _mm_set1_ps(1.0f - tx), right = _mm_set1_ps(tx);
  const __m128 row0 = _mm_add_ps(_mm_mul_ps(left, texel_lanes<kBytes>(level, x0, y0)),
                                 _mm_mul_ps(right, texel_lanes<kBytes>(level, x1, y0)));
  const __m128 row1 = _mm_add_ps(_mm_mul_ps(left, texel_lanes<kBytes>(level, x0, y1)),
                                 _mm_mul_ps(right, texel_lanes<kBytes>(level, x1, y1)));
  const __m128 value = _mm_add_ps(_mm_mul_ps(_mm_set1_ps(1.0f - ty), row0), _mm_mul_ps(_mm_set1_ps(ty), row1));
  glm::vec4 out;
  _mm_storeu_ps(&out.x, value);
  return out;
}

}  // namespace

struct Texture::Decoded {
  TexelLevel level0;
  bool convert_srgb_after_filtering = false;  // 8- and 16-bit sRGB data: decoded after filtering
  bool associated_alpha = false;              // premultiplied at load
};

// Premultiplies an sRGB image with alpha on its encoded values (Blender's Straight alpha mode).
void Texture::associate_alpha(Decoded& decoded) {
  for (glm::vec4& t : decoded.level0.floats) t = glm::vec4(glm::vec3(t) * t.w, t.w);
  decoded.associated_alpha = true;
}

Texture::~Texture() = default;

Texture::Decoded Texture::decode_floats(int width, int height, int channels, const float* pixels,
                                        const std::string& name) {
  if (width <= 0 || height <= 0 || channels < 1 || channels > 4 || pixels == nullptr)
    throw std::invalid_argument(name + ": texture needs a positive size and 1 to 4 channels");
  require_texture_memory(name, width, height, 0.0);
  Decoded decoded;
  TexelLevel& level = decoded.level0;
  level.width = width;
  level.height = height;
  level.floats.resize(static_cast<size_t>(width) * height);
  for (int y = 0; y < height; ++y) {
    // Stored bottom row first so that v = 0 is row 0.
    const float* row = pixels + static_cast<size_t>(height - 1 - y) * width * channels;
    for (int x = 0; x < width; ++x) {
      glm::vec4 t = to_rgba(row + static_cast<size_t>(x) * channels, channels);
      if (!std::isfinite(t.x) || !std::isfinite(t.y) || !std::isfinite(t.z) || !std::isfinite(t.w))
        throw std::runtime_error(name + ": texel (" + std::to_string(x) + ", " + std::to_string(height - 1 - y) +
                                 ") is not finite");
      level.floats[static_cast<size_t>(y) * width + x] = t;
    }
  }
  return decoded;
}

Texture::Decoded Texture::decode_bytes(int width, int height, int channels, const uint8_t* pixels,
                                       ColorSpace space, const std::string& name) {
  if (pixels == nullptr) throw std::invalid_argument(name + ": no pixel data");
  if (width <= 0 || height <= 0 || channels < 1 || channels > 4)
    throw std::invalid_argument(name + ": texture needs a positive size and 1 to 4 channels");
  if (space == ColorSpace::SRGB && channels == 4) {
    // Premultiplied, so kept as floats; 8-bit sRGB images are filtered on the encoded values
    // and decoded afterwards (Cycles).
    require_texture_memory(name, width, height, 4.0 * channels);
    std::vector<float> values(static_cast<size_t>(width) * height * channels);
    for (size_t i = 0; i < values.size(); ++i) values[i] = pixels[i] / 255.0f;
    Decoded decoded = decode_floats(width, height, channels, values.data(), name);
    associate_alpha(decoded);
    decoded.convert_srgb_after_filtering = true;
    return decoded;
  }
  // Kept as bytes, expanded to RGBA (grey to RGB, alpha 255 when absent), bottom row first.
  require_texture_memory(name, width, height, 0.0, 4.0);
  Decoded decoded;
  decoded.convert_srgb_after_filtering = space == ColorSpace::SRGB;
  TexelLevel& level = decoded.level0;
  level.width = width;
  level.height = height;
  level.bytes.resize(static_cast<size_t>(width) * height * 4);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const uint8_t* p = pixels + (static_cast<size_t>(height - 1 - y) * width + x) * channels;
      uint8_t* t = &level.bytes[(static_cast<size_t>(y) * width + x) * 4];
      t[0] = p[0];
      t[1] = channels >= 3 ? p[1] : p[0];
      t[2] = channels >= 3 ? p[2] : p[0];
      t[3] = channels == 4 ? p[3] : channels == 2 ? p[1] : 255;
    }
  return decoded;
}

namespace {

// An image file's pixels as OpenImageIO reads them: 8-bit bytes, or floats for any other format.
struct FilePixels {
  int width = 0, height = 0, channels = 0;
  OIIO::TypeDesc::BASETYPE format = OIIO::TypeDesc::UNKNOWN;
  std::vector<uint8_t> bytes;
  std::vector<float> floats;
};

// OpenImageIO's error text, which may hold several lines (each layer's say), as one.
std::string one_line(std::string text) {
  text = matbase::trim(text);
  for (size_t at; (at = text.find('\n')) != std::string::npos;) text.replace(at, 1, "; ");
  return text;
}

FilePixels read_file_pixels(const std::string& path) {
  // Straight colour as stored (Cycles' default alpha mode); OpenImageIO would premultiply.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto input = OIIO::ImageInput::open(path, &config);
  if (!input) throw std::runtime_error(path + ": cannot read image: " + one_line(OIIO::geterror()));
  const OIIO::ImageSpec& spec = input->spec();
  FilePixels pixels{spec.width, spec.height, std::min(spec.nchannels, 4),
                    static_cast<OIIO::TypeDesc::BASETYPE>(spec.format.basetype), {}, {}};
  if (pixels.width <= 0 || pixels.height <= 0 || pixels.channels < 1) throw std::runtime_error(path + ": image has no pixels");
  const size_t values = static_cast<size_t>(pixels.width) * pixels.height * pixels.channels;
  bool read = false;
  if (pixels.format == OIIO::TypeDesc::UINT8) {
    require_texture_memory(path, pixels.width, pixels.height, pixels.channels, 4.0);
    pixels.bytes.resize(values);
    read = input->read_image(0, 0, 0, pixels.channels, OIIO::TypeDesc::UINT8, pixels.bytes.data());
  } else {
    require_texture_memory(path, pixels.width, pixels.height, 4.0 * pixels.channels);
    pixels.floats.resize(values);
    read = input->read_image(0, 0, 0, pixels.channels, OIIO::TypeDesc::FLOAT, pixels.floats.data());
  }
  if (!read) throw std::runtime_error(path + ": cannot decode image: " + one_line(input->geterror()));
  input->close();
  return pixels;
}

// read_file_pixels with what libpng prints on standard error ("libpng error: IDAT: ...", before
// OpenImageIO reports the same in its error, which names the file) taken out of the way.
FilePixels read_file_pixels_quietly(const std::string& path) {
  matbase::StandardErrorCapture capture;
  const auto pass_on = [&capture] { matbase::pass_on_other_lines(capture.take(), {"libpng ", "PNG library error"}); };
  try {
    FilePixels pixels = read_file_pixels(path);
    pass_on();
    return pixels;
  } catch (...) {
    pass_on();
    throw;
  }
}

}  // namespace

Texture::Decoded Texture::decode_file(const std::string& path, ColorSpace space) {
  matbase::require_input_file(path);
  require_plausible_header(path);
  FilePixels pixels = read_file_pixels_quietly(path);
  const int width = pixels.width, height = pixels.height, channels = pixels.channels;
  if (pixels.format == OIIO::TypeDesc::UINT8) return decode_bytes(width, height, channels, pixels.bytes.data(), space, path);
  std::vector<float>& floats = pixels.floats;
  if (space == ColorSpace::SRGB && pixels.format == OIIO::TypeDesc::UINT16) {
    // As for 8-bit images: interpolate encoded values, decode after filtering.
    Decoded decoded = decode_floats(width, height, channels, floats.data(), path);
    decoded.convert_srgb_after_filtering = true;
    if (channels == 4) associate_alpha(decoded);
    return decoded;
  }
  if (space == ColorSpace::SRGB) {
    // Float images tagged sRGB are decoded once at load time (Cycles converts float images
    // through OCIO when loading).
    for (size_t i = 0; i < floats.size(); ++i)
      if (channels < 4 || i % 4 != 3) floats[i] = matbase::srgb_to_linear(floats[i]);
  }
  return decode_floats(width, height, channels, floats.data(), path);
}

std::shared_ptr<const Texture> Texture::with_texels(Decoded decoded, ColorSpace space, TextureWrap wrap, std::string name,
                                                    std::function<TexelLevel()> remake) {
  auto texture = std::shared_ptr<Texture>(new Texture());
  texture->width_ = decoded.level0.width;
  texture->height_ = decoded.level0.height;
  texture->space_ = space;
  texture->wrap_ = wrap;
  texture->name_ = std::move(name);
  texture->convert_srgb_after_filtering_ = decoded.convert_srgb_after_filtering;
  texture->associated_alpha_ = decoded.associated_alpha;
  const bool evictable = static_cast<bool>(remake);
  if (!remake) remake = [] () -> TexelLevel { throw std::logic_error("a texture cache entry that stays was dropped"); };
  texture->levels_.push_back(std::make_unique<TexelPage>(std::move(remake), evictable));
  // Each mip level is made from the finer one, whose texels it pins only while filtering.
  Texture* const self = texture.get();
  for (size_t i = 1; i < mip_level_count(texture->width_, texture->height_); ++i)
    texture->levels_.push_back(
        std::make_unique<TexelPage>([self, i] { return box_filtered_half(*self->levels_[i - 1]->acquire(TexelPage::Use::Source)); }, true));
  texture->levels_.front()->install(std::move(decoded.level0));
  return texture;
}

std::shared_ptr<const Texture> Texture::from_pixelsf(int width, int height, int channels,
                                                     const float* pixels, ColorSpace space, TextureWrap wrap,
                                                     std::string name) {
  Decoded decoded = decode_floats(width, height, channels, pixels, name);
  return with_texels(std::move(decoded), space, wrap, std::move(name), nullptr);
}

std::shared_ptr<const Texture> Texture::from_pixels8(int width, int height, int channels,
                                                     const uint8_t* pixels, ColorSpace space, TextureWrap wrap,
                                                     std::string name) {
  Decoded decoded = decode_bytes(width, height, channels, pixels, space, name);
  return with_texels(std::move(decoded), space, wrap, std::move(name), nullptr);
}

std::shared_ptr<const Texture> Texture::load(const std::string& path, ColorSpace space, TextureWrap wrap) {
  if (path.find(kUdimToken) != std::string::npos) return load_udim(path, space, wrap);
  return load_file(path, space, wrap, nullptr);
}

std::shared_ptr<const Texture> Texture::load_radiance(const std::string& path, ColorSpace space) {
  return load_file(path, space, TextureWrap::Repeat, clamp_compression_negatives);
}

std::shared_ptr<const Texture> Texture::load_file(const std::string& path, ColorSpace space, TextureWrap wrap,
                                                  void (*adjust)(TexelLevel&, const std::string&)) {
  const auto decode = [path, space, adjust] {
    Decoded decoded = decode_file(path, space);
    if (adjust) adjust(decoded.level0, path);
    return decoded;
  };
  Decoded decoded = decode();
  const int width = decoded.level0.width, height = decoded.level0.height;
  auto remake = [decode, path, width, height] {
    TexelLevel level = decode().level0;
    if (level.width != width || level.height != height)
      throw std::runtime_error(path + ": changed while rendering: " + std::to_string(width) + " x " +
                               std::to_string(height) + " texels when loaded, now " + std::to_string(level.width) +
                               " x " + std::to_string(level.height));
    return level;
  };
  return with_texels(std::move(decoded), space, wrap, path, std::move(remake));
}

ColorSpace blender_default_color_space(const std::string& path) {
  matbase::require_input_file(path);
  auto input = OIIO::ImageInput::open(path);
  if (!input) throw std::runtime_error(path + ": cannot read image: " + OIIO::geterror());
  const OIIO::TypeDesc::BASETYPE type = static_cast<OIIO::TypeDesc::BASETYPE>(input->spec().format.basetype);
  input->close();
  const bool float_data = type == OIIO::TypeDesc::FLOAT || type == OIIO::TypeDesc::HALF || type == OIIO::TypeDesc::DOUBLE;
  return float_data ? ColorSpace::NonColor : ColorSpace::SRGB;
}

const TexelLevel& Texture::texels(size_t level) const { return pinned_texels(*levels_[level]); }

glm::vec4 Texture::bilinear(const TexelLevel& level, glm::vec2 uv) const {
  // Texel centres sit at (i + 0.5) / W.
  const float x = uv.x * level.width - 0.5f;
  const float y = uv.y * level.height - 0.5f;
  if (!std::isfinite(x) || !std::isfinite(y)) return level.texel(0, 0);
  const float fx = std::floor(x);
  const float fy = std::floor(y);
  const float tx = x - fx;
  const float ty = y - fy;
  // Most lookups fall inside the image and need neither reduction (fmod and an integer
  // division were 3 % of the textured vase's instructions). Elsewhere, reduce before narrowing
  // to int so that huge or far-out UVs stay well defined. f is a whole number: within int's
  // range the integer remainder is fmod's, exactly, in a fraction of its instructions (repeated
  // maps, and the small mip levels, take this path often).
  const auto index = [&](float f, int offset, int n) {
    if (f >= 0.0f && f < static_cast<float>(n - offset)) return static_cast<int>(f) + offset;
    if (wrap_ == TextureWrap::Repeat) {
      constexpr float kIntRange = 0x1p30f;
      // In (-n, n]: a remainder in (-n, n), plus 0 or 1.
      const int i = (std::abs(f) < kIntRange ? static_cast<int>(f) % n
                                             : static_cast<int>(std::fmod(f, static_cast<float>(n)))) +
                    offset;
      return i < 0 ? i + n : (i >= n ? i - n : i);
    }
    return wrap_index(static_cast<int>(std::clamp(f, -1.0f, static_cast<float>(n))) + offset, n, wrap_);
  };
  const int x0 = index(fx, 0, level.width);
  const int x1 = index(fx, 1, level.width);
  const int y0 = index(fy, 0, level.height);
  const int y1 = index(fy, 1, level.height);
  return level.stored_as_bytes() ? blend_texels<true>(level, x0, x1, y0, y1, tx, ty)
                                 : blend_texels<false>(level, x0, x1, y0, y1, tx, ty);
}

std::shared_ptr<const Texture> Texture::load_udim(const std::string& pattern, ColorSpace space, TextureWrap wrap) {
  const size_t token = pattern.find(kUdimToken);
  const fs::path folder = fs::path(pattern.substr(0, token)).parent_path();
  const std::string prefix = fs::path(pattern.substr(0, token)).filename().string();
  const std::string suffix = pattern.substr(token + kUdimToken.size());
  auto texture = std::shared_ptr<Texture>(new Texture());
  texture->space_ = space;
  texture->wrap_ = wrap;
  texture->name_ = pattern;
  std::error_code error;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder.empty() ? fs::path(".") : folder, error)) {
    const std::string name = entry.path().filename().string();
    if (name.size() != prefix.size() + 4 + suffix.size() || name.compare(0, prefix.size(), prefix) != 0 ||
        name.compare(prefix.size() + 4, suffix.size(), suffix) != 0)
      continue;
    const std::string digits = name.substr(prefix.size(), 4);
    if (!std::all_of(digits.begin(), digits.end(), [](unsigned char c) { return std::isdigit(c); })) continue;
    const int number = std::stoi(digits);
    if (number < 1001) continue;
    // Every tile's header now, so that a broken one is an error before rendering, not during.
    require_plausible_header(entry.path().string());
    auto input = OIIO::ImageInput::open(entry.path().string());
    if (!input) throw std::runtime_error(entry.path().string() + ": cannot read image: " + OIIO::geterror());
    auto tile = std::make_unique<UdimTile>();
    tile->number = number;
    tile->path = entry.path().string();
    tile->width = input->spec().width;
    tile->height = input->spec().height;
    texture->udim_.push_back(std::move(tile));
  }
  if (error) throw std::runtime_error(pattern + ": cannot list its folder: " + error.message());
  if (texture->udim_.empty())
    throw std::runtime_error(pattern + ": no UDIM tile files (" + prefix + "1001" + suffix + ", ...) found");
  std::sort(texture->udim_.begin(), texture->udim_.end(),
            [](const auto& a, const auto& b) { return a->number < b->number; });
  // The set reports its first tile's size.
  texture->width_ = texture->udim_.front()->width;
  texture->height_ = texture->udim_.front()->height;
  return texture;
}

std::vector<int> Texture::udim_tiles() const {
  std::vector<int> numbers;
  for (const auto& tile : udim_) numbers.push_back(tile->number);
  return numbers;
}

size_t Texture::loaded_udim_tiles() const {
  size_t loaded = 0;
  for (const auto& tile : udim_) loaded += std::atomic_load(&tile->texture) != nullptr;
  return loaded;
}

glm::vec4 Texture::sample_udim(glm::vec2 uv, bool unassociate, float footprint) const {
  // Cycles' missing-texture colour (util/texture.h, TEX_IMAGE_MISSING_*), linear.
  const glm::vec4 missing(1.0f, 0.0f, 1.0f, 1.0f);
  // Truncated toward zero, as Cycles casts them (svm_node_tex_image); 9999 rows bound the number.
  const float fu = std::trunc(uv.x), fv = std::trunc(uv.y);
  if (!(fu >= 0.0f && fu < 10.0f && fv >= 0.0f && fv < 9999.0f)) return missing;
  const int number = 1001 + static_cast<int>(fu) + 10 * static_cast<int>(fv);
  const auto it = std::lower_bound(udim_.begin(), udim_.end(), number,
                                   [](const auto& tile, int n) { return tile->number < n; });
  if (it == udim_.end() || (*it)->number != number) return missing;
  UdimTile& tile = **it;
  std::call_once(tile.loaded, [&] { std::atomic_store(&tile.texture, load(tile.path, space_, wrap_)); });
  return tile.texture->sample(uv - glm::vec2(fu, fv), unassociate, footprint);
}

glm::vec4 Texture::sample(glm::vec2 uv, bool unassociate, float footprint) const {
  if (!udim_.empty()) return sample_udim(uv, unassociate, footprint);
  // The level whose texels are as wide as the footprint: lod = log2(footprint in level-0 texels).
  const float texels_across = footprint * static_cast<float>(std::max(width_, height_));
  glm::vec4 value;
  if (!(texels_across > 1.0f)) {
    value = bilinear(texels(0), uv);
  } else {
    const float lod = std::min(std::log2(texels_across), static_cast<float>(levels_.size() - 1));
    const size_t fine = static_cast<size_t>(lod);
    const float t = lod - static_cast<float>(fine);
    value = bilinear(texels(fine), uv);
    if (t > 0.0f && fine + 1 < levels_.size()) value = (1.0f - t) * value + t * bilinear(texels(fine + 1), uv);
  }
  if (unassociate && associated_alpha_ && value.w > 0.0f) {
    value.x /= value.w;
    value.y /= value.w;
    value.z /= value.w;
  }
  if (convert_srgb_after_filtering_) {
    value.x = matbase::srgb_to_linear(value.x);
    value.y = matbase::srgb_to_linear(value.y);
    value.z = matbase::srgb_to_linear(value.z);
  }
  return value;
}

}  // namespace matrender
