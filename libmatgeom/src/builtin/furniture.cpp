// Placeholder while the generators are written: every object a plain box.
#include "builtin/objects.h"
#include "builtin/object_builder.h"
#include "builtin/shapes.h"

namespace matgeom::builtin {
namespace {
ObjectAsset placeholder(uint32_t seed) {
  ObjectBuilder b(seed);
  const uint32_t part = b.add_part("body", Finish::Plastic);
  b.add(part, box_mesh(glm::dvec3(-0.2, -0.2, 0.0), glm::dvec3(0.2, 0.2, 0.4)));
  return b.finish();
}
}  // namespace
ObjectAsset make_table(uint32_t seed) { return placeholder(seed); }
ObjectAsset make_chair(uint32_t seed) { return placeholder(seed); }
ObjectAsset make_stool(uint32_t seed) { return placeholder(seed); }
ObjectAsset make_desk(uint32_t seed) { return placeholder(seed); }
ObjectAsset make_cabinet(uint32_t seed) { return placeholder(seed); }
ObjectAsset make_shelf(uint32_t seed) { return placeholder(seed); }
ObjectAsset make_sofa(uint32_t seed) { return placeholder(seed); }
ObjectAsset make_bed(uint32_t seed) { return placeholder(seed); }
}  // namespace matgeom::builtin
