#pragma once
// The material classes, declared once: the ids the label AOV holds, their names, the colours
// label maps are drawn in, and what each class models. Ids 0 to 7 are the MatPredict
// repository's (docs/matpredict_repository.md, "Material families and label ids"), so our label
// maps read the same in its tools; the classes it lacks follow from 8. The procedural library,
// the MatSynth-folder loader, the built-in objects, the scene file, the dataset writer and the
// evaluation reports all take classes from this table.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace matmaterial {

enum class MaterialClass : int32_t {
  Background = 0,
  Concrete = 1,
  Fabric = 2,
  Leather = 3,
  Metal = 4,
  Plastic = 5,
  Stone = 6,
  Wood = 7,
  Marble = 8,
  Ceramic = 9,
  Terracotta = 10,
  Plaster = 11,
  Rubber = 12,
  Paper = 13,
  Glass = 14,
};
constexpr size_t kMaterialClassCount = 15;

struct MaterialClassInfo {
  MaterialClass id;
  const char* name;               // lower case, as folder names and scene files spell it
  std::array<uint8_t, 3> colour;  // 8-bit sRGB colour of its label in visualisations
  const char* description;        // what the class models, one line for --list-materials
};

// Colours: the repository's for ids 0 to 7 (mostly the dark half of ColorBrewer's "Paired"
// scheme), then its light half, and a teal from ColorBrewer's "Set2" for glass.
constexpr std::array<MaterialClassInfo, kMaterialClassCount> kMaterialClasses = {{
    {MaterialClass::Background, "background", {30, 30, 30}, "no object: what the camera sees past it"},
    {MaterialClass::Concrete, "concrete", {230, 85, 13}, "cast cement: grey, rough, speckled with aggregate and pores"},
    {MaterialClass::Fabric, "fabric", {49, 130, 189}, "woven cloth: threads in a weave, sheen at grazing angles"},
    {MaterialClass::Leather, "leather", {227, 26, 28}, "tanned hide: pebbled grain, satin"},
    {MaterialClass::Metal, "metal", {106, 61, 154}, "bare metal (metallic 1): brushed, polished, worn"},
    {MaterialClass::Plastic, "plastic", {255, 127, 0}, "moulded polymer: saturated colour, smooth to matte"},
    {MaterialClass::Stone, "stone", {177, 89, 40}, "natural rock: granite, slate and sandstone grains"},
    {MaterialClass::Wood, "wood", {51, 160, 44}, "timber: growth rings and pores, raw or lacquered (clearcoat)"},
    {MaterialClass::Marble, "marble", {202, 178, 214}, "polished marble: veined, glossy"},
    {MaterialClass::Ceramic, "ceramic", {166, 206, 227}, "glazed ceramic: mottled glaze under a clearcoat"},
    {MaterialClass::Terracotta, "terracotta", {253, 191, 111}, "unglazed fired clay: orange-brown, rough, porous"},
    {MaterialClass::Plaster, "plaster", {255, 255, 153}, "painted plaster: off-white, matte, trowel marks"},
    {MaterialClass::Rubber, "rubber", {251, 154, 153}, "rubber: dark, rough, fine texture"},
    {MaterialClass::Paper, "paper", {178, 223, 138}, "paper and cardboard: fibres, corrugation, perforations"},
    {MaterialClass::Glass, "glass", {102, 194, 165}, "clear and tinted glass: transmission with its IOR"},
}};

constexpr const MaterialClassInfo& material_class(MaterialClass id) {
  return kMaterialClasses[static_cast<size_t>(id)];
}

// The id the label AOV holds for the class.
constexpr int32_t label_id(MaterialClass id) { return static_cast<int32_t>(id); }

// The class of a label id, if the table has it.
std::optional<MaterialClass> material_class_of_label(int32_t label);

// The class a name spells ("wood"), if any.
std::optional<MaterialClass> material_class_named(std::string_view name);

// The class a material folder's name gives, the repository's rule: the name is a class's or
// starts with it and '_' ("wood_3"), case-insensitively. Background is never a folder's class.
std::optional<MaterialClass> material_class_of_folder(std::string_view folder_name);

// The class's name for a label id, or "class <id>" outside the table.
std::string label_name(int32_t label);

// The label's visualisation colour; grey outside the table.
std::array<uint8_t, 3> label_colour(int32_t label);

// The table as the markdown table of docs/scene_format.md (a test holds the docs to it).
std::string material_classes_markdown();

}  // namespace matmaterial
