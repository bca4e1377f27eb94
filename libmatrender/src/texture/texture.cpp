#include "matrender/texture.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include <OpenImageIO/imageio.h>

#include "matgeom/input_file.h"
#include "matgeom/memory_limit.h"
#include "matgeom/srgb.h"

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
  matgeom::require_memory(texels * (texel_bytes + staging_bytes_per_texel),
                          "its " + std::to_string(width) + " x " + std::to_string(height) + " texels", name);
}

int wrap_index(int i, int n, Wrap wrap) {
  if (wrap == Wrap::Clamp) return i < 0 ? 0 : (i >= n ? n - 1 : i);
  const int r = i % n;
  return r < 0 ? r + n : r;
}

}  // namespace

std::shared_ptr<Texture> Texture::without_texels(int width, int height, ColorSpace space, Wrap wrap, std::string name) {
  auto texture = std::shared_ptr<Texture>(new Texture());
  texture->width_ = width;
  texture->height_ = height;
  texture->space_ = space;
  texture->wrap_ = wrap;
  texture->name_ = std::move(name);
  return texture;
}

std::shared_ptr<const Texture> Texture::from_pixelsf(int width, int height, int channels,
                                                     const float* pixels, ColorSpace space, Wrap wrap,
                                                     std::string name) {
  if (width <= 0 || height <= 0 || channels < 1 || channels > 4 || pixels == nullptr)
    throw std::invalid_argument(name + ": texture needs a positive size and 1 to 4 channels");
  auto texture = without_texels(width, height, space, wrap, std::move(name));
  texture->texels_.resize(static_cast<size_t>(width) * height);
  for (int y = 0; y < height; ++y) {
    // Stored bottom row first so that v = 0 is row 0.
    const float* row = pixels + static_cast<size_t>(height - 1 - y) * width * channels;
    for (int x = 0; x < width; ++x) {
      glm::vec4 t = to_rgba(row + static_cast<size_t>(x) * channels, channels);
      if (!std::isfinite(t.x) || !std::isfinite(t.y) || !std::isfinite(t.z) || !std::isfinite(t.w))
        throw std::runtime_error(texture->name_ + ": texel (" + std::to_string(x) + ", " +
                                 std::to_string(height - 1 - y) + ") is not finite");
      texture->texels_[static_cast<size_t>(y) * width + x] = t;
    }
  }
  return texture;
}

std::shared_ptr<const Texture> Texture::from_pixels8(int width, int height, int channels,
                                                     const uint8_t* pixels, ColorSpace space, Wrap wrap,
                                                     std::string name) {
  if (pixels == nullptr) throw std::invalid_argument(name + ": no pixel data");
  if (width <= 0 || height <= 0 || channels < 1 || channels > 4)
    throw std::invalid_argument(name + ": texture needs a positive size and 1 to 4 channels");
  if (!(space == ColorSpace::SRGB && channels == 4)) {
    // Kept as bytes, expanded to RGBA (grey to RGB, alpha 255 when absent), bottom row first.
    require_texture_memory(name, width, height, 0.0, 4.0);
    auto texture = without_texels(width, height, space, wrap, std::move(name));
    texture->convert_srgb_after_filtering_ = space == ColorSpace::SRGB;
    texture->bytes_.resize(static_cast<size_t>(width) * height * 4);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const uint8_t* p = pixels + (static_cast<size_t>(height - 1 - y) * width + x) * channels;
        uint8_t* t = &texture->bytes_[(static_cast<size_t>(y) * width + x) * 4];
        t[0] = p[0];
        t[1] = channels >= 3 ? p[1] : p[0];
        t[2] = channels >= 3 ? p[2] : p[0];
        t[3] = channels == 4 ? p[3] : channels == 2 ? p[1] : 255;
      }
    return texture;
  }
  require_texture_memory(name, width, height, 4.0 * channels);
  std::vector<float> values(static_cast<size_t>(width) * height * channels);
  for (size_t i = 0; i < values.size(); ++i) values[i] = pixels[i] / 255.0f;
  // 8-bit sRGB images are filtered on the encoded values and decoded afterwards (Cycles).
  auto texture = from_pixelsf(width, height, channels, values.data(), ColorSpace::NonColor, wrap,
                              std::move(name));
  auto mutable_texture = std::const_pointer_cast<Texture>(texture);
  mutable_texture->space_ = space;
  mutable_texture->convert_srgb_after_filtering_ = space == ColorSpace::SRGB;
  if (space == ColorSpace::SRGB && channels == 4) mutable_texture->associate_alpha();
  return texture;
}

void Texture::associate_alpha() {
  for (glm::vec4& t : texels_) t = glm::vec4(glm::vec3(t) * t.w, t.w);
  associated_alpha_ = true;
}

std::shared_ptr<const Texture> Texture::load(const std::string& path, ColorSpace space, Wrap wrap) {
  if (path.find(kUdimToken) != std::string::npos) return load_udim(path, space, wrap);
  matgeom::require_input_file(path);
  // Straight colour as stored (Cycles' default alpha mode); OpenImageIO would premultiply.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto input = OIIO::ImageInput::open(path, &config);
  if (!input) throw std::runtime_error(path + ": cannot read image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = input->spec();
  const int channels = std::min(spec.nchannels, 4);
  if (spec.width <= 0 || spec.height <= 0 || channels < 1)
    throw std::runtime_error(path + ": image has no pixels");
  if (spec.format.basetype == OIIO::TypeDesc::UINT8) {
    require_texture_memory(path, spec.width, spec.height, channels, 4.0);
    std::vector<uint8_t> bytes(static_cast<size_t>(spec.width) * spec.height * channels);
    if (!input->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, bytes.data()))
      throw std::runtime_error(path + ": cannot decode image: " + input->geterror());
    input->close();
    return from_pixels8(spec.width, spec.height, channels, bytes.data(), space, wrap, path);
  }
  require_texture_memory(path, spec.width, spec.height, 4.0 * channels);
  std::vector<float> pixels(static_cast<size_t>(spec.width) * spec.height * channels);
  if (!input->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data()))
    throw std::runtime_error(path + ": cannot decode image: " + input->geterror());
  input->close();

  const bool integer_format = spec.format.basetype == OIIO::TypeDesc::UINT8 ||
                              spec.format.basetype == OIIO::TypeDesc::UINT16;
  if (space == ColorSpace::SRGB && integer_format) {
    // As for 8-bit images: interpolate encoded values, decode after filtering.
    auto texture = from_pixelsf(spec.width, spec.height, channels, pixels.data(),
                                ColorSpace::NonColor, wrap, path);
    auto mutable_texture = std::const_pointer_cast<Texture>(texture);
    mutable_texture->space_ = space;
    mutable_texture->convert_srgb_after_filtering_ = true;
    if (channels == 4) mutable_texture->associate_alpha();
    return texture;
  }
  if (space == ColorSpace::SRGB) {
    // Float images tagged sRGB are decoded once at load time (Cycles converts float images
    // through OCIO when loading).
    for (size_t i = 0; i < pixels.size(); ++i)
      if (channels < 4 || i % 4 != 3) pixels[i] = matgeom::srgb_to_linear(pixels[i]);
  }
  return from_pixelsf(spec.width, spec.height, channels, pixels.data(), space, wrap, path);
}

ColorSpace blender_default_color_space(const std::string& path) {
  matgeom::require_input_file(path);
  auto input = OIIO::ImageInput::open(path);
  if (!input) throw std::runtime_error(path + ": cannot read image: " + OIIO::geterror());
  const OIIO::TypeDesc::BASETYPE type = static_cast<OIIO::TypeDesc::BASETYPE>(input->spec().format.basetype);
  input->close();
  const bool float_data = type == OIIO::TypeDesc::FLOAT || type == OIIO::TypeDesc::HALF || type == OIIO::TypeDesc::DOUBLE;
  return float_data ? ColorSpace::NonColor : ColorSpace::SRGB;
}

Texture::Level Texture::level(size_t i) const {
  const auto stored = [](int w, int h, const std::vector<glm::vec4>& floats, const std::vector<uint8_t>& bytes) {
    return Level{w, h, floats.data(), bytes.empty() ? nullptr : bytes.data()};
  };
  if (i == 0) return stored(width_, height_, texels_, bytes_);
  const MipLevel& m = mips_[i - 1];
  return stored(m.width, m.height, m.floats, m.bytes);
}

size_t Texture::level_count() const { return 1 + mips_.size(); }

void Texture::build_mips() const {
  // Each level halves the sides (rounding up) and averages the 2 x 2 texels below each texel,
  // edge texels repeated on odd sides, down to 1 x 1.
  // Levels are stored as level 0 is (byte levels round to the nearest byte); together they take
  // a third of its memory.
  Level parent = level(0);
  const bool bytes = !bytes_.empty();
  require_texture_memory(name_ + " (mip levels)", width_, height_, 0.0, bytes ? 4.0 / 3.0 : 16.0 / 3.0);
  while (parent.width > 1 || parent.height > 1) {
    MipLevel next{std::max(1, (parent.width + 1) / 2), std::max(1, (parent.height + 1) / 2), {}, {}};
    const size_t count = static_cast<size_t>(next.width) * next.height;
    if (bytes) next.bytes.resize(4 * count); else next.floats.resize(count);
    for (int y = 0; y < next.height; ++y)
      for (int x = 0; x < next.width; ++x) {
        const auto at = [&](int px, int py) {
          return parent.texel(std::min(px, parent.width - 1), std::min(py, parent.height - 1));
        };
        const glm::vec4 mean =
            0.25f * (at(2 * x, 2 * y) + at(2 * x + 1, 2 * y) + at(2 * x, 2 * y + 1) + at(2 * x + 1, 2 * y + 1));
        const size_t i = static_cast<size_t>(y) * next.width + x;
        if (!bytes) {
          next.floats[i] = mean;
          continue;
        }
        for (int c = 0; c < 4; ++c) next.bytes[4 * i + c] = static_cast<uint8_t>(std::lround(mean[c] * 255.0f));
      }
    mips_.push_back(std::move(next));
    parent = level(mips_.size());
  }
}

glm::vec4 Texture::bilinear(const Level& level, glm::vec2 uv) const {
  // Texel centres sit at (i + 0.5) / W.
  const float x = uv.x * level.width - 0.5f;
  const float y = uv.y * level.height - 0.5f;
  if (!std::isfinite(x) || !std::isfinite(y)) return level.texel(0, 0);
  const float fx = std::floor(x);
  const float fy = std::floor(y);
  const float tx = x - fx;
  const float ty = y - fy;
  // Reduce before narrowing to int so that huge or far-out UVs stay well defined.
  const auto index = [&](float f, int offset, int n) {
    const float reduced = wrap_ == Wrap::Repeat ? std::fmod(f, static_cast<float>(n))
                                                : std::clamp(f, -1.0f, static_cast<float>(n));
    return wrap_index(static_cast<int>(reduced) + offset, n, wrap_);
  };
  const int x0 = index(fx, 0, level.width);
  const int x1 = index(fx, 1, level.width);
  const int y0 = index(fy, 0, level.height);
  const int y1 = index(fy, 1, level.height);
  const auto texel = [&](int ix, int iy) { return level.texel(ix, iy); };
  return (1.0f - ty) * ((1.0f - tx) * texel(x0, y0) + tx * texel(x1, y0)) +
         ty * ((1.0f - tx) * texel(x0, y1) + tx * texel(x1, y1));
}

std::shared_ptr<const Texture> Texture::load_udim(const std::string& pattern, ColorSpace space, Wrap wrap) {
  const size_t token = pattern.find(kUdimToken);
  const fs::path folder = fs::path(pattern.substr(0, token)).parent_path();
  const std::string prefix = fs::path(pattern.substr(0, token)).filename().string();
  const std::string suffix = pattern.substr(token + kUdimToken.size());
  auto texture = without_texels(0, 0, space, wrap, pattern);
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
  const float fu = std::floor(uv.x), fv = std::floor(uv.y);
  if (!(fu >= 0.0f && fu < 10.0f && fv >= 0.0f && fv < 1000.0f)) return glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  const int number = 1001 + static_cast<int>(fu) + 10 * static_cast<int>(fv);
  const auto it = std::lower_bound(udim_.begin(), udim_.end(), number,
                                   [](const auto& tile, int n) { return tile->number < n; });
  if (it == udim_.end() || (*it)->number != number) return glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
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
    value = bilinear(level(0), uv);
  } else {
    std::call_once(mips_built_, [this] { build_mips(); });
    const float lod = std::min(std::log2(texels_across), static_cast<float>(level_count() - 1));
    const size_t fine = static_cast<size_t>(lod);
    const float t = lod - static_cast<float>(fine);
    value = bilinear(level(fine), uv);
    if (t > 0.0f && fine + 1 < level_count()) value = (1.0f - t) * value + t * bilinear(level(fine + 1), uv);
  }
  if (unassociate && associated_alpha_ && value.w > 0.0f) {
    value.x /= value.w;
    value.y /= value.w;
    value.z /= value.w;
  }
  if (convert_srgb_after_filtering_) {
    value.x = matgeom::srgb_to_linear(value.x);
    value.y = matgeom::srgb_to_linear(value.y);
    value.z = matgeom::srgb_to_linear(value.z);
  }
  return value;
}

}  // namespace matrender
