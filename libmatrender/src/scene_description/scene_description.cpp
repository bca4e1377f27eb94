#include "matrender/scene_description.h"

namespace matrender {

std::string Origin::describe(const std::string& child) const {
  if (!pointer) return source;
  const std::string where = *pointer + child;
  return where.empty() ? source : source + ": " + where;
}

matbase::InputError Origin::error(const std::string& child, const std::string& message) const {
  return matbase::InputError(describe(child) + ": " + message);
}

}  // namespace matrender
