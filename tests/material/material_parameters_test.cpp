// The one table of material parameters: well formed, and the docs say what it says.
#include <catch2/catch.hpp>

#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

#include "matgeom/object_asset.h"
#include "matmaterial/material_parameters.h"

using namespace matgeom;

TEST_CASE("Every material parameter has a unique name, a default within its range, and is found by name", "[geom]") {
  std::set<std::string> names;
  for (const matmaterial::MaterialParameterInfo& info : matmaterial::kMaterialParameters) {
    CAPTURE(info.name);
    CHECK(names.insert(info.name).second);
    CHECK(info.min <= info.default_value);
    CHECK(info.default_value <= info.max);
    CHECK(std::string(info.blender_input).size() > 0);
    CHECK(info.packed_channel >= 0);
    CHECK(info.packed_channel <= 3);
    REQUIRE(matmaterial::material_parameter_named(info.name));
    CHECK(*matmaterial::material_parameter_named(info.name) == info.id);
    CHECK(&matmaterial::material_parameter(info.id) == &info);
  }
  CHECK_FALSE(matmaterial::material_parameter_named("base_colour"));
  // The glTF packing: roughness in G, metallic in B.
  CHECK(matmaterial::material_parameter(matmaterial::MaterialParameter::Roughness).packed_channel == 1);
  CHECK(matmaterial::material_parameter(matmaterial::MaterialParameter::Metallic).packed_channel == 2);
  CHECK(matmaterial::material_parameter(matmaterial::MaterialParameter::BaseColor).texture_space == matmaterial::ColorSpace::SRGB);
}

TEST_CASE("docs/scene_format.md and the README list the material parameters exactly as the table has them",
          "[geom]") {
  for (const char* path : {MATPREDICT_SCENE_FORMAT_DOC, MATPREDICT_README}) {
    std::ifstream in(path);
    REQUIRE(in);
    std::stringstream text;
    text << in.rdbuf();
    INFO(path << ": regenerate the table with: render_object --list-parameters");
    CHECK(text.str().find(matmaterial::material_parameters_markdown()) != std::string::npos);
  }
}

TEST_CASE("An asset material starts at the table's defaults and takes images only where the table allows", "[geom]") {
  const matmaterial::MaterialInputs desc("slot");
  CHECK(desc.name == "slot");
  for (const matmaterial::MaterialParameterInfo& info : matmaterial::kMaterialParameters) {
    CAPTURE(info.name);
    CHECK(desc.color(info.id) == glm::dvec3(info.default_value));
    CHECK(desc[info.id].image == -1);
    matmaterial::MaterialInputs textured;
    if (info.texturable) {
      textured.set_image(info.id, 0, 3);
      CHECK(textured[info.id].image == 0);
      CHECK(textured[info.id].channel == 3);
    } else {
      CHECK_THROWS_AS(textured.set_image(info.id, 0), std::invalid_argument);
    }
  }
  matmaterial::MaterialInputs any;
  CHECK_THROWS_AS(any.set_image(matmaterial::MaterialParameter::Roughness, 0, 4), std::invalid_argument);
}

TEST_CASE("Image channels read as the renderer expands images to RGBA", "[geom]") {
  const matbase::ImagePixels grey{"grey", 2, 1, 1, {7, 9}};
  const matbase::ImagePixels grey_alpha{"grey_alpha", 1, 1, 2, {7, 100}};
  const matbase::ImagePixels rgb{"rgb", 2, 1, 3, {1, 2, 3, 4, 5, 6}};
  const matbase::ImagePixels rgba{"rgba", 1, 1, 4, {1, 2, 3, 4}};
  for (int c = 0; c < 3; ++c) {
    CHECK(matbase::texel_channel(grey, 1, c) == 9);
    CHECK(matbase::texel_channel(grey_alpha, 0, c) == 7);
    CHECK(matbase::texel_channel(rgb, 1, c) == 4 + c);
    CHECK(matbase::texel_channel(rgba, 0, c) == 1 + c);
  }
  CHECK(matbase::texel_channel(grey, 0, 3) == 255);
  CHECK(matbase::texel_channel(grey_alpha, 0, 3) == 100);
  CHECK(matbase::texel_channel(rgb, 0, 3) == 255);
  CHECK(matbase::texel_channel(rgba, 0, 3) == 4);
}
