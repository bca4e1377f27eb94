// Our glTF files read by another project's reader: Blender 3.4's own glTF importer (optional:
// MATPREDICT_BLENDER_TESTS, ctest label "blender"). For every row of the material table the
// Principled BSDF input Blender builds must hold what read_gltf makes of the same file: the same
// constant, or an image where read_gltf has one. That holds the writer and the reader to
// Blender's mapping at once (docs/conventions.md, "What Blender's glTF importer makes of a
// metallic-roughness material").
#include <filesystem>
#include <string>

#include <catch2/catch.hpp>

#include "matgeom/gltf_reader.h"
#include "matgeom/gltf_writer.h"
#include "matgeom/material_parameters.h"
#include "matgeom/mesh.h"
#include "matgeom/tangents.h"
#include "shaders_ref/cycles_reference.h"

namespace {

using matgeom::MaterialDesc;
using P = matgeom::MaterialParameter;

// A quad of two triangles, one per part, with UVs.
matgeom::ObjectAsset two_material_quad() {
  matgeom::ObjectAsset asset;
  matgeom::TriangleMesh& mesh = asset.mesh;
  mesh.positions = {{0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}};
  mesh.uvs = {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.0f, 1.0f}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  mesh.triangle_parts = {0, 1};
  mesh.part_names = {"lacquer", "textured"};
  matgeom::compute_vertex_normals(mesh);
  matgeom::ImagePixels rgb{"rgb.png", 2, 2, 3, {}};
  for (int k = 0; k < 12; ++k) rgb.data.push_back(static_cast<uint8_t>(20 * k));
  asset.images = {rgb};

  // Constants everywhere the table and glTF allow, away from Blender's defaults.
  MaterialDesc lacquer("lacquer");
  lacquer.set(P::BaseColor, glm::dvec3(0.5, 0.25, 0.125));
  lacquer.set(P::Metallic, 0.3);
  lacquer.set(P::Roughness, 0.6);
  lacquer.set(P::Emission, glm::dvec3(0.2, 0.1, 0.05));
  lacquer.set(P::EmissionStrength, 3.0);
  lacquer.set(P::Clearcoat, 0.75);
  lacquer.set(P::ClearcoatRoughness, 0.2);
  lacquer.set(P::Ior, 1.33);
  lacquer.set(P::Transmission, 0.3);
  lacquer.set(P::Alpha, 0.8);
  // Every input glTF can texture, from the one image.
  MaterialDesc textured("textured");
  textured.set_image(P::BaseColor, 0);
  textured.set_image(P::Alpha, 0, 3);  // the base colour's alpha
  textured.set_metallic_roughness_image(0);
  textured.set(P::Emission, glm::dvec3(1.0));
  textured.set_image(P::Emission, 0);
  textured.set(P::Clearcoat, 1.0);
  textured.set_image(P::Clearcoat, 0, 0);
  textured.set(P::ClearcoatRoughness, 1.0);
  textured.set_image(P::ClearcoatRoughness, 0, 1);
  textured.set(P::Transmission, 0.5);
  textured.set_image(P::Transmission, 0, 0);
  asset.materials = {lacquer, textured};
  return asset;
}

}  // namespace

TEST_CASE("Blender's glTF importer makes of our glTF files what read_gltf makes", "[render][blender]") {
  REQUIRE(shaders_ref::cycles_available());
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "matpredict_blender_gltf_import";
  std::filesystem::create_directories(folder);
  const std::string path = (folder / "quad.glb").string();
  matgeom::write_gltf(two_material_quad(), path);
  const matgeom::ObjectAsset ours = matgeom::read_gltf(path);
  const shaders_ref::BlenderMaterials blender = shaders_ref::import_gltf_with_blender(path, folder.string());

  REQUIRE(ours.materials.size() == 2);
  for (const MaterialDesc& material : ours.materials) {
    REQUIRE(blender.count(material.name) == 1);
    const auto& inputs = blender.at(material.name);
    for (const matgeom::MaterialParameterInfo& info : matgeom::kMaterialParameters) {
      CAPTURE(material.name, info.name);
      REQUIRE(inputs.count(info.blender_input) == 1);
      const shaders_ref::BlenderInput& input = inputs.at(info.blender_input);
      const matgeom::MaterialInput& mine = material[info.id];
      CHECK(input.linked == (mine.image >= 0));
      if (input.linked) continue;
      REQUIRE(input.value.size() == (info.kind == matgeom::ParameterKind::Color ? 3u : 1u));
      // Blender stores single-precision floats.
      for (size_t c = 0; c < input.value.size(); ++c) CHECK(input.value[c] == Approx(mine.value[c]).margin(1e-6));
    }
  }
}
