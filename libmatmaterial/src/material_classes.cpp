#include "matmaterial/material_classes.h"

#include "matbase/text.h"

namespace matmaterial {
namespace {

constexpr bool rows_in_id_order() {
  for (size_t i = 0; i < kMaterialClasses.size(); ++i)
    if (static_cast<size_t>(kMaterialClasses[i].id) != i) return false;
  return true;
}
static_assert(rows_in_id_order(), "kMaterialClasses must list the classes in id order");

}  // namespace

std::optional<MaterialClass> material_class_of_label(int32_t label) {
  if (label < 0 || static_cast<size_t>(label) >= kMaterialClassCount) return std::nullopt;
  return static_cast<MaterialClass>(label);
}

std::optional<MaterialClass> material_class_named(std::string_view name) {
  for (const MaterialClassInfo& info : kMaterialClasses)
    if (name == info.name) return info.id;
  return std::nullopt;
}

std::optional<MaterialClass> material_class_of_folder(std::string_view folder_name) {
  const std::string name = matbase::lowercase(folder_name);
  for (const MaterialClassInfo& info : kMaterialClasses) {
    if (info.id == MaterialClass::Background) continue;
    const std::string_view class_name = info.name;
    if (name == class_name || (name.size() > class_name.size() && name.compare(0, class_name.size(), class_name) == 0 &&
                               name[class_name.size()] == '_'))
      return info.id;
  }
  return std::nullopt;
}

std::string label_name(int32_t label) {
  const std::optional<MaterialClass> c = material_class_of_label(label);
  return c ? material_class(*c).name : "class " + std::to_string(label);
}

std::array<uint8_t, 3> label_colour(int32_t label) {
  const std::optional<MaterialClass> c = material_class_of_label(label);
  return c ? material_class(*c).colour : std::array<uint8_t, 3>{128, 128, 128};
}

std::string material_classes_markdown() {
  std::string table =
      "| id | class | label colour | models |\n"
      "|----|-------|--------------|--------|\n";
  for (const MaterialClassInfo& info : kMaterialClasses)
    table += "| " + std::to_string(label_id(info.id)) + " | `" + info.name + "` | (" + std::to_string(info.colour[0]) +
             ", " + std::to_string(info.colour[1]) + ", " + std::to_string(info.colour[2]) + ") | " + info.description +
             " |\n";
  return table;
}

}  // namespace matmaterial
