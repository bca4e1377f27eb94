// The one table of material parameters: well formed, and the docs say what it says.
#include <catch2/catch.hpp>

#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "matgeom/material_parameters.h"

using namespace matgeom;

TEST_CASE("Every material parameter has a unique name, a default within its range, and is found by name", "[geom]") {
  std::set<std::string> names;
  for (const MaterialParameterInfo& info : kMaterialParameters) {
    CAPTURE(info.name);
    CHECK(names.insert(info.name).second);
    CHECK(info.min <= info.default_value);
    CHECK(info.default_value <= info.max);
    CHECK(std::string(info.blender_input).size() > 0);
    CHECK(info.packed_channel >= 0);
    CHECK(info.packed_channel <= 3);
    REQUIRE(material_parameter_named(info.name));
    CHECK(*material_parameter_named(info.name) == info.id);
    CHECK(&material_parameter(info.id) == &info);
  }
  CHECK_FALSE(material_parameter_named("base_colour"));
  // The glTF packing: roughness in G, metallic in B.
  CHECK(material_parameter(MaterialParameter::Roughness).packed_channel == 1);
  CHECK(material_parameter(MaterialParameter::Metallic).packed_channel == 2);
  CHECK(material_parameter(MaterialParameter::BaseColor).texture_space == ColorSpace::SRGB);
}

TEST_CASE("docs/scene_format.md lists the material parameters exactly as the table has them", "[geom]") {
  std::ifstream in(MATPREDICT_SCENE_FORMAT_DOC);
  REQUIRE(in);
  std::stringstream text;
  text << in.rdbuf();
  INFO("regenerate the table with: render_object --list-parameters");
  CHECK(text.str().find(material_parameters_markdown()) != std::string::npos);
}
