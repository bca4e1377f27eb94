// The texture cache's memory bound (matrender/texture_cache.h): levels past the limit are
// dropped, made again when looked up, and the pixels never change.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include "matrender/camera.h"
#include "matrender/render.h"
#include "matrender/scene.h"
#include "matrender/texture.h"
#include "matrender/texture_cache.h"
#include "test_scenes.h"
#include "texture/texel_cache.h"

using namespace matrender;
namespace fs = std::filesystem;

namespace {

fs::path temp_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("matrender_cache_test_" + name + "_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

void write_rgb_png(const fs::path& path, int size, const std::vector<uint8_t>& pixels) {
  auto out = OIIO::ImageOutput::create(path.string());
  REQUIRE(out);
  REQUIRE(out->open(path.string(), OIIO::ImageSpec(size, size, 3, OIIO::TypeDesc::UINT8)));
  REQUIRE(out->write_image(OIIO::TypeDesc::UINT8, pixels.data()));
  out->close();
}

// Texture k: one colour, (20 k, 7, 255 - 20 k) as data, so a lookup says which file it read.
fs::path write_constant_png(const fs::path& dir, int k, int size) {
  std::vector<uint8_t> pixels;
  for (int i = 0; i < size * size; ++i)
    pixels.insert(pixels.end(), {static_cast<uint8_t>(20 * k), 7, static_cast<uint8_t>(255 - 20 * k)});
  const fs::path path = dir / ("constant_" + std::to_string(k) + ".png");
  write_rgb_png(path, size, pixels);
  return path;
}

bool is_constant_colour(const glm::vec4& texel, int k) {
  const glm::vec4 expected = glm::vec4(20.0f * k, 7.0f, 255.0f - 20.0f * k, 255.0f) / 255.0f;
  return glm::all(glm::lessThanEqual(glm::abs(texel - expected), glm::vec4(1e-6f)));
}

// Restores the default limit whatever a test does.
struct LimitGuard {
  ~LimitGuard() { set_texture_memory_limit(0); }
};

}  // namespace

TEST_CASE("Past its limit the cache drops the least recently used levels and decodes them again", "[render]") {
  LimitGuard guard;
  release_pinned_texels();
  const fs::path dir = temp_dir("lru");
  constexpr int kSize = 64, kTextures = 6;
  constexpr uint64_t kLevel0Bytes = kSize * kSize * 4;  // 8-bit RGB is kept as RGBA bytes
  // What stays of other tests' textures whatever the limit.
  set_texture_memory_limit(1);
  const uint64_t before = texture_cache_stats().resident_bytes;
  set_texture_memory_limit(before + 3 * kLevel0Bytes);
  reset_texture_cache_counters();

  std::vector<TexturePtr> textures;
  for (int k = 0; k < kTextures; ++k)
    textures.push_back(Texture::load(write_constant_png(dir, k, kSize).string(), ColorSpace::NonColor));
  // Loading the six decoded each, and the cache kept the last three.
  TextureCacheStats stats = texture_cache_stats();
  CHECK(stats.evictions == kTextures - 3);
  CHECK(stats.resident_bytes <= before + 3 * kLevel0Bytes);
  CHECK(stats.reloads == 0);
  // Two rounds of lookups: each one of a dropped texture decodes its file again.
  for (int round = 0; round < 2; ++round)
    for (int k = 0; k < kTextures; ++k) {
      CHECK(is_constant_colour(textures[k]->sample({0.3f, 0.7f}), k));
      release_pinned_texels();
    }
  stats = texture_cache_stats();
  CHECK(stats.reloads == 2 * kTextures);  // least recently used goes first: each lookup misses
  CHECK(stats.peak_bytes <= before + 4 * kLevel0Bytes);  // the limit, and the level being made
  CHECK(stats.resident_bytes <= before + 3 * kLevel0Bytes);

  // A mip level is filtered from its finer level, made again first if it was dropped.
  const float level_3 = 8.0f / kSize;  // a footprint of 8 texels: level 3 alone
  CHECK(is_constant_colour(textures[0]->sample({0.5f, 0.5f}, false, level_3), 0));
  release_pinned_texels();
  // Texels in memory only (no file to decode again) stay whatever the limit.
  const uint8_t red[3] = {255, 0, 0};
  const TexturePtr memory = Texture::from_pixels8(1, 1, 3, red, ColorSpace::NonColor);
  set_texture_memory_limit(1);
  CHECK(memory->sample({0.5f, 0.5f}) == glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
  CHECK(is_constant_colour(textures[5]->sample({0.5f, 0.5f}), 5));
  release_pinned_texels();
  fs::remove_all(dir);
}

TEST_CASE("A texture file changed on disk after its level 0 was dropped is an error naming it", "[render]") {
  LimitGuard guard;
  release_pinned_texels();
  const fs::path dir = temp_dir("changed");
  const fs::path path = write_constant_png(dir, 1, 16);
  const TexturePtr texture = Texture::load(path.string(), ColorSpace::NonColor);
  write_constant_png(dir, 1, 32);
  set_texture_memory_limit(1);  // drops every level that can go
  CHECK_THROWS_WITH(texture->sample({0.5f, 0.5f}),
                    Catch::Contains(path.string() + ": changed while rendering: 16 x 16 texels when loaded, now 32 x 32"));
  fs::remove_all(path);
  CHECK_THROWS_WITH(texture->sample({0.5f, 0.5f}), Catch::Contains(path.string()));
  fs::remove_all(dir);
}

TEST_CASE("A render in a cache far smaller than its textures gives the same pixels", "[render]") {
  LimitGuard guard;
  release_pinned_texels();
  // Six planes side by side, each with its own 256 x 256 checker of a different period, seen at
  // a grazing angle so that lookups read several mip levels of each.
  const fs::path dir = temp_dir("render");
  constexpr int kSize = 256;
  // What stays of other tests' textures whatever the limit.
  set_texture_memory_limit(1);
  const uint64_t before = texture_cache_stats().resident_bytes;
  set_texture_memory_limit(0);
  Scene scene;
  for (int k = 0; k < 6; ++k) {
    std::vector<uint8_t> pixels;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        const bool dark = ((x >> (k + 1)) + (y >> (k + 1))) % 2 == 1;
        pixels.insert(pixels.end(), {static_cast<uint8_t>(dark ? 30 : 220), static_cast<uint8_t>(40 * k), 90});
      }
    const fs::path path = dir / ("checker_" + std::to_string(k) + ".png");
    write_rgb_png(path, kSize, pixels);
    Material m;
    m[MaterialParameter::BaseColor] = {glm::vec3(1.0f), Texture::load(path.string(), ColorSpace::SRGB), 0};
    matgeom::TriangleMesh plane = test_scenes::horizontal_square(1.0, 0.0);
    for (glm::vec3& p : plane.positions) p.x += 2.0f * (k - 2.5f);
    scene.add_mesh(plane, {scene.add_material(m)});
  }
  scene.add_lamp(PointLamp{glm::dvec3(0.0, -2.0, 3.0), 2000.0, glm::dvec3(1.0)});
  scene.set_background(glm::vec3(0.3f));
  RenderSettings settings;
  settings.samples_per_pixel = 4;
  settings.threads = 2;
  const Camera camera = Camera::look_at({0.0, -6.0, 1.2}, {0.0, 0.0, 0.0}, {0, 0, 1}, 1.2, 48, 32);
  FrameBuffers unbounded, bounded;
  render(scene, camera, settings, unbounded);
  // Everything dropped, then a sixteenth of what the first render held: the second makes its
  // levels again within that.
  const uint64_t held = texture_cache_stats().resident_bytes - before;
  reset_texture_cache_counters();
  set_texture_memory_limit(1);
  set_texture_memory_limit(before + held / 16);
  render(scene, camera, settings, bounded);
  const TextureCacheStats stats = texture_cache_stats();
  CHECK(stats.evictions > 0);
  CHECK(stats.reloads > 0);
  CHECK(bounded.color == unbounded.color);
  fs::remove_all(dir);
}
