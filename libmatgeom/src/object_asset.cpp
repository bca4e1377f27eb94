#include "matgeom/object_asset.h"

namespace matgeom {

MaterialDesc default_material(const std::string& name) {
  MaterialDesc desc;
  desc.name = name;
  desc.base_color = glm::dvec3(0.8);
  desc.metallic = 0.0;
  desc.roughness = 0.5;
  return desc;
}

}  // namespace matgeom
