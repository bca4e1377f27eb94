// The HDRIs Debian's blender-data ships as real lossy-compressed environment maps (optional:
// MATPREDICT_BLENDER_TESTS, which installs Blender and so blender-data): each carries small
// negative components from its DWAB compression, and every one must load, clamped, with none refused
// (texture/negative_radiance.h).
#include <filesystem>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "matrender/texture.h"

TEST_CASE("blender-data's HDRIs load as environment maps, their compression's negatives clamped", "[blender]") {
  const std::filesystem::path folder = "/usr/share/blender/datafiles/studiolights/world";
  std::vector<std::string> maps;
  if (std::filesystem::is_directory(folder))
    for (const auto& entry : std::filesystem::directory_iterator(folder))
      if (entry.path().extension() == ".exr") maps.push_back(entry.path().string());
  REQUIRE(maps.size() >= 8);
  for (const std::string& path : maps) {
    INFO(path);
    const auto map = matrender::Texture::load_radiance(path, matrender::ColorSpace::NonColor);
    REQUIRE(map->width() > 0);
    for (int y = 0; y < map->height(); y += 7)
      for (int x = 0; x < map->width(); x += 7) {
        const glm::vec4 texel = map->sample({(x + 0.5f) / map->width(), (y + 0.5f) / map->height()});
        CHECK(texel.x >= 0.0f);
        CHECK(texel.y >= 0.0f);
        CHECK(texel.z >= 0.0f);
      }
  }
}
