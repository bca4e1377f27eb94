// Which UDIM tile a UV reads, against Blender 3.4 Cycles itself (optional: MATPREDICT_BLENDER_TESTS,
// ctest label "blender"): a UV left of tile 1001 (u in (-1, 0), truncated to tile 1001), a tile
// the set lacks (magenta) and a tile it has, rendered by Cycles and looked up by Texture.
#include <filesystem>

#include <catch2/catch.hpp>

#include "matrender/texture.h"
#include "shaders_ref/cycles_reference.h"

TEST_CASE("UDIM lookups land where Cycles' do: truncated UVs, and magenta for a missing tile", "[render][blender]") {
  REQUIRE(shaders_ref::cycles_available());
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "matpredict_blender_udim";
  const std::vector<shaders_ref::UdimProbe> probes = shaders_ref::probe_udim_with_blender(folder.string());
  REQUIRE(probes.size() == 3);
  const matrender::TexturePtr set =
      matrender::Texture::load((folder / "probe.<UDIM>.png").string(), matmaterial::ColorSpace::NonColor);
  for (const shaders_ref::UdimProbe& probe : probes) {
    const glm::vec4 ours = set->sample(probe.uv);
    CAPTURE(probe.name, probe.cycles_rgb.x, probe.cycles_rgb.y, probe.cycles_rgb.z, ours.x, ours.y, ours.z);
    for (int c = 0; c < 3; ++c) CHECK(ours[c] == Approx(probe.cycles_rgb[c]).margin(1e-4));
  }
}
