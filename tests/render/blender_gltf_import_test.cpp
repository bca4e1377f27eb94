// Our glTF files read by another project's reader: Blender 3.4's own glTF importer (optional:
// MATPREDICT_BLENDER_TESTS, ctest label "blender"). For every row of the material table the
// node input Blender builds (the Principled BSDF's, or the Velvet BSDF's it adds for glTF's sheen)
// must hold what read_gltf makes of the same file: the same constant, or an image where read_gltf
// has one. That holds the writer and the reader to
// Blender's mapping at once (docs/conventions.md, "What Blender's glTF importer makes of a
// metallic-roughness material").
#include <cmath>
#include <filesystem>
#include <string>

#include <catch2/catch.hpp>

#include "matgeom/io/gltf/gltf_reader.h"
#include "matgeom/io/gltf/gltf_writer.h"
#include "matgeom/mesh.h"
#include "matgeom/tangents.h"
#include "matmaterial/material_parameters.h"
#include "matmaterial/texture_transform.h"
#include "shaders_ref/cycles_reference.h"

namespace {

using matmaterial::MaterialInputs;
using P = matmaterial::MaterialParameter;

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
  matbase::ImagePixels rgb{"rgb.png", 2, 2, 3, {}};
  for (int k = 0; k < 12; ++k) rgb.data.push_back(static_cast<uint8_t>(20 * k));
  asset.images = {rgb};

  // Constants everywhere the table and glTF allow, away from Blender's defaults.
  MaterialInputs lacquer("lacquer");
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
  lacquer.set(P::VelvetColor, glm::dvec3(0.6, 0.3, 0.2));
  lacquer.set(P::VelvetSigma, 0.4);
  // Every input glTF can texture, from the one image, each textureInfo placed on the UVs its own
  // way (KHR_texture_transform; the identity for the base colour).
  const auto placed = [](double k) {
    return matmaterial::TextureTransform{{0.1 * k, -0.2 + 0.05 * k}, 0.3 * k - 0.5, {1.0 + 0.5 * k, 2.0 - 0.25 * k}};
  };
  MaterialInputs textured("textured");
  textured.set_image(P::BaseColor, 0);
  textured.set_image(P::Alpha, 0, 3);  // the base colour's alpha
  textured.set_metallic_roughness_image(0, placed(1));
  textured.set(P::Emission, glm::dvec3(1.0));
  textured.set_image(P::Emission, 0, 0, placed(2));
  textured.set(P::Clearcoat, 1.0);
  textured.set_image(P::Clearcoat, 0, 0, placed(3));
  textured.set(P::ClearcoatRoughness, 1.0);
  textured.set_image(P::ClearcoatRoughness, 0, 1, placed(4));
  textured.set(P::Transmission, 0.5);
  textured.set_image(P::Transmission, 0, 0, placed(5));
  textured.set(P::VelvetColor, glm::dvec3(0.9, 0.8, 0.7));
  textured.set_image(P::VelvetColor, 0, 0, placed(7));
  textured.set(P::VelvetSigma, 0.5);
  textured.set_image(P::VelvetSigma, 0, 3, placed(8));
  textured.normal_image = 0;
  textured.normal_transform = placed(6);
  asset.materials = {lacquer, textured};
  return asset;
}

// Where Blender's Mapping node puts uv: R_z(rotation) (scale * uv) + location.
glm::dvec2 blender_mapped(const shaders_ref::BlenderUvMapping& m, glm::dvec2 uv) {
  const glm::dvec2 scaled(m.scale[0] * uv.x, m.scale[1] * uv.y);
  const double c = std::cos(m.rotation_z), s = std::sin(m.rotation_z);
  return {c * scaled.x - s * scaled.y + m.location[0], s * scaled.x + c * scaled.y + m.location[1]};
}

// The image behind `input` lies on the UVs where our transform puts it: the same point for
// UVs across and beyond the unit square.
void check_placement(const shaders_ref::BlenderInput& input, const matmaterial::TextureTransform& transform) {
  if (transform.is_identity()) {
    CHECK_FALSE(input.mapping.has_value());
    return;
  }
  REQUIRE(input.mapping.has_value());
  const matmaterial::UvAffine ours = matmaterial::uv_affine(transform);
  for (const glm::dvec2 uv : {glm::dvec2(0.0), glm::dvec2(1.0, 0.0), glm::dvec2(0.3, 0.8), glm::dvec2(-1.5, 2.25)}) {
    const glm::dvec2 blender = blender_mapped(*input.mapping, uv);
    const glm::vec2 mine = ours.apply(glm::vec2(uv));
    CAPTURE(uv.x, uv.y);
    CHECK(mine.x == Approx(blender.x).margin(1e-5));
    CHECK(mine.y == Approx(blender.y).margin(1e-5));
  }
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
  for (const MaterialInputs& material : ours.materials) {
    REQUIRE(blender.count(material.name) == 1);
    const shaders_ref::BlenderNodes& nodes = blender.at(material.name);
    // Both materials have a velvet: the importer must have added one to each.
    REQUIRE(material.color(P::VelvetColor) != glm::dvec3(0.0));
    for (const matmaterial::MaterialParameterInfo& info : matmaterial::kMaterialParameters) {
      CAPTURE(material.name, info.name);
      const char* node = matmaterial::blender_node_name(info.node);
      REQUIRE(nodes.count(node) == 1);
      const auto& inputs = nodes.at(node);
      REQUIRE(inputs.count(info.blender_input) == 1);
      const shaders_ref::BlenderInput& input = inputs.at(info.blender_input);
      const matmaterial::MaterialInput& mine = material[info.id];
      CHECK(input.linked == (mine.image >= 0));
      if (input.linked) {
        // Blender has one Alpha link, from the base colour's image.
        check_placement(input, mine.transform);
        continue;
      }
      REQUIRE(input.value.size() == (info.kind == matmaterial::ParameterKind::Color ? 3u : 1u));
      // Blender stores single-precision floats.
      for (size_t c = 0; c < input.value.size(); ++c) CHECK(input.value[c] == Approx(mine.value[c]).margin(1e-6));
    }
    const auto& principled = nodes.at("Principled BSDF");
    REQUIRE(principled.count("Normal") == 1);
    CHECK(principled.at("Normal").linked == (material.normal_image >= 0));
    if (material.normal_image >= 0) check_placement(principled.at("Normal"), material.normal_transform);
    // The velvet keeps the smooth normal, as our renderer shades it.
    CHECK_FALSE(nodes.at("Velvet BSDF").at("Normal").linked);
  }
}
