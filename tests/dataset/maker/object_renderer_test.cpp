// make_dataset's ObjectRenderer as a library: what it hands other renderers (variant_asset, the
// object written as glTF for Blender) holds the materials its own frames are rendered with.
#include <catch2/catch.hpp>

#include <cstdint>
#include <filesystem>
#include <vector>

#include "matdataset/maker/dataset_config.h"
#include "matdataset/maker/object_renderer.h"
#include "matgeom/object_asset.h"
#include "matrender/asset.h"
#include "matrender/material.h"

TEST_CASE("The exported variant reads every map where the dataset's frames read it", "[dataset]") {
  // Hammered metal's maps repeat to their physical size on each part of the vase (a repeat count
  // that is not a whole number), its normal map included: the export must place each map as the
  // renderer does, or Blender shows the dents elsewhere.
  const matdataset::DatasetConfig config = matdataset::parse_config(
      "objects:\n  - {name: vase, builtin: vase, materials: {all: [metal/hammered:4]}}\n"
      "camera: {grid: [1, 1]}\nrender: {resolution: 16, samples: 1, material_resolution: 32}\n",
      "object_renderer_test", std::filesystem::temp_directory_path(), {});
  matdataset::ObjectRenderer renderer(config, 0);
  renderer.select_variant(0, {0});
  const matgeom::ObjectAsset exported = renderer.variant_asset();
  const std::vector<uint32_t>& ids = renderer.part_materials();
  REQUIRE(exported.materials.size() == ids.size());
  int textured_inputs = 0;
  for (size_t part = 0; part < ids.size(); ++part) {
    const matrender::Material& rendered = renderer.scene().material(ids[part]);
    const matrender::Material as_exported = matrender::material_from_desc(exported.materials[part], exported.images);
    REQUIRE(static_cast<bool>(rendered.normal_map) == static_cast<bool>(as_exported.normal_map));
    for (const glm::vec2 uv : {glm::vec2(0.0f), glm::vec2(1.0f, 0.0f), glm::vec2(0.3f, 0.8f), glm::vec2(0.9f, 0.1f)}) {
      if (rendered.normal_map) {
        const glm::vec2 a = rendered.normal_map_uv_transform.apply(uv);
        const glm::vec2 b = as_exported.normal_map_uv_transform.apply(uv);
        CHECK(glm::length(a - b) < 1e-4f);
      }
      for (size_t p = 0; p < rendered.parameters.size(); ++p) {
        if (!rendered.parameters[p].texture) continue;
        ++textured_inputs;
        const glm::vec2 a = rendered.parameters[p].uv_transform.apply(uv);
        const glm::vec2 b = as_exported.parameters[p].uv_transform.apply(uv);
        CHECK(glm::length(a - b) < 1e-4f);
      }
    }
  }
  CHECK(textured_inputs > 0);
}
