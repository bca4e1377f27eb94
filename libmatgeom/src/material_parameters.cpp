#include "matgeom/material_parameters.h"

namespace matgeom {
namespace {

constexpr bool rows_in_enum_order() {
  for (size_t i = 0; i < kMaterialParameters.size(); ++i)
    if (static_cast<size_t>(kMaterialParameters[i].id) != i) return false;
  return true;
}
static_assert(rows_in_enum_order(), "kMaterialParameters must list the parameters in MaterialParameter order");

}  // namespace

std::optional<MaterialParameter> material_parameter_named(std::string_view name) {
  for (const MaterialParameterInfo& info : kMaterialParameters)
    if (name == info.name) return info.id;
  return std::nullopt;
}

}  // namespace matgeom
