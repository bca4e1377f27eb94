#include "matmaterial/material_parameters.h"

#include <cstdio>

namespace matmaterial {
namespace {

constexpr bool rows_in_enum_order() {
  for (size_t i = 0; i < kMaterialParameters.size(); ++i)
    if (static_cast<size_t>(kMaterialParameters[i].id) != i) return false;
  return true;
}
static_assert(rows_in_enum_order(), "kMaterialParameters must list the parameters in MaterialParameter order");

// Shortest decimal form: 0.8, 1.45, 1000.
std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

}  // namespace

std::string material_parameters_markdown() {
  std::string table =
      "| key | default | value | Blender input |\n"
      "|-----|---------|-------|---------------|\n";
  for (const MaterialParameterInfo& info : kMaterialParameters) {
    const bool color = info.kind == ParameterKind::Color;
    const std::string d = number(info.default_value);
    const std::string range = "[" + number(info.min) + ", " + number(info.max) + "]";
    std::string value = color ? "`[r, g, b]` with components in " + range : "number in " + range;
    if (info.texturable) value += color ? ", or a [colour texture](#textures)" : ", or a [scalar texture](#textures)";
    // Principled BSDF inputs by their name alone, the others with their node's.
    const std::string input = info.node == BlenderNode::PrincipledBsdf
                                  ? std::string(info.blender_input)
                                  : std::string(blender_node_name(info.node)) + " " + info.blender_input;
    table += "| `" + std::string(info.name) + "` | `" + (color ? "[" + d + ", " + d + ", " + d + "]" : d) + "` | " +
             value + ": " + info.description + " | " + input + " |\n";
  }
  return table;
}

std::optional<MaterialParameter> material_parameter_named(std::string_view name) {
  for (const MaterialParameterInfo& info : kMaterialParameters)
    if (name == info.name) return info.id;
  return std::nullopt;
}

}  // namespace matmaterial
