// The one table of material classes: the MatPredict repository's ids, names and colours kept, the
// repository's folder-name rule, and the docs saying what the table says.
#include "matmaterial/material_classes.h"

#include <catch2/catch.hpp>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

using namespace matmaterial;

TEST_CASE("Material class ids 0 to 7 are the MatPredict repository's, with its colours", "[geom]") {
  // docs/matpredict_repository.md, section 3: the ids its label maps hold.
  const struct {
    int id;
    const char* name;
    std::array<uint8_t, 3> colour;
  } repository[] = {{0, "background", {30, 30, 30}}, {1, "concrete", {230, 85, 13}}, {2, "fabric", {49, 130, 189}},
                    {3, "leather", {227, 26, 28}},   {4, "metal", {106, 61, 154}},   {5, "plastic", {255, 127, 0}},
                    {6, "stone", {177, 89, 40}},     {7, "wood", {51, 160, 44}}};
  for (const auto& family : repository) {
    CAPTURE(family.name);
    REQUIRE(matmaterial::material_class_named(family.name));
    CHECK(matmaterial::label_id(*matmaterial::material_class_named(family.name)) == family.id);
    CHECK(matmaterial::label_name(family.id) == family.name);
    CHECK(matmaterial::label_colour(family.id) == family.colour);
  }
}

TEST_CASE("Every material class has a unique name and colour and is found by name and by label", "[geom]") {
  std::set<std::string> names;
  std::set<std::array<uint8_t, 3>> colours;
  for (const matmaterial::MaterialClassInfo& info : matmaterial::kMaterialClasses) {
    CAPTURE(info.name);
    CHECK(names.insert(info.name).second);
    CHECK(colours.insert(info.colour).second);
    CHECK(std::string(info.description).size() > 10);
    CHECK(matmaterial::material_class_named(info.name) == info.id);
    CHECK(matmaterial::material_class_of_label(matmaterial::label_id(info.id)) == info.id);
    CHECK(&matmaterial::material_class(info.id) == &info);
  }
  // The fourteen classes, and the background.
  CHECK(matmaterial::kMaterialClassCount == 15);
  for (const char* name : {"wood", "concrete", "fabric", "leather", "plastic", "stone", "metal", "marble", "ceramic",
                           "terracotta", "plaster", "rubber", "paper", "glass"})
    CHECK(matmaterial::material_class_named(name));
  CHECK_FALSE(matmaterial::material_class_named("Wood"));
  CHECK_FALSE(matmaterial::material_class_of_label(-1));
  CHECK_FALSE(matmaterial::material_class_of_label(15));
  CHECK(matmaterial::label_name(70) == "class 70");
  CHECK(matmaterial::label_colour(70) == std::array<uint8_t, 3>{128, 128, 128});
}

TEST_CASE("A material folder's class follows from its name as in the repository", "[geom]") {
  CHECK(matmaterial::material_class_of_folder("wood") == matmaterial::MaterialClass::Wood);
  CHECK(matmaterial::material_class_of_folder("wood_3") == matmaterial::MaterialClass::Wood);
  CHECK(matmaterial::material_class_of_folder("Fabric_Velvet_02") == matmaterial::MaterialClass::Fabric);
  CHECK(matmaterial::material_class_of_folder("metal_") == matmaterial::MaterialClass::Metal);
  // A longer word is not its prefix's class, and the background is nobody's folder.
  CHECK_FALSE(matmaterial::material_class_of_folder("woodland"));
  CHECK_FALSE(matmaterial::material_class_of_folder("metallic_paint"));
  CHECK_FALSE(matmaterial::material_class_of_folder("background"));
  CHECK_FALSE(matmaterial::material_class_of_folder("background_1"));
  CHECK_FALSE(matmaterial::material_class_of_folder(""));
  CHECK_FALSE(matmaterial::material_class_of_folder("_wood"));
}

TEST_CASE("docs/scene_format.md lists the material classes exactly as the table has them", "[geom]") {
  std::ifstream in(MATPREDICT_SCENE_FORMAT_DOC);
  REQUIRE(in);
  std::stringstream text;
  text << in.rdbuf();
  INFO("regenerate the table with: render_object --list-materials");
  CHECK(text.str().find(matmaterial::material_classes_markdown()) != std::string::npos);
}
