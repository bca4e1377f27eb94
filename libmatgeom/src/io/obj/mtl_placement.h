#pragma once
// A map's placement as MTL writes it (-o and -s) and as MaterialInputs holds it (a TextureTransform).
// Blender 3.4's importer (io/wavefront_obj/importer/obj_import_mtl.cc) puts a Mapping node of type
// Point between the UVs and the Image Texture, Location = -o and Scale = -s: out = Location +
// Scale x in, so the image is looked up at uv' = s uv + o on OBJ's UVs, which are ours (v up).
// Only u and v place the texture: the image lookup ignores the third component, w.
#include <optional>

#include <glm/glm.hpp>

#include "matmaterial/texture_transform.h"

namespace matgeom::obj {

struct MtlPlacement {
  glm::dvec2 origin{0.0};  // -o u v
  glm::dvec2 scale{1.0};   // -s u v
};

// texture_transform.h's map without rotation is u' = sx u + ox, v' = sy v + (1 - oy - sy) on our
// UVs, since glTF's offset moves v down the image. It is u' = su u + ou, v' = sv v + ov when
// scale = (su, sv), ox = ou and oy = 1 - sv - ov.
inline matmaterial::TextureTransform texture_transform(const MtlPlacement& placement) {
  matmaterial::TextureTransform transform;
  transform.scale = placement.scale;
  transform.offset = {placement.origin.x, 1.0 - placement.scale.y - placement.origin.y};
  return transform;
}

// The inverse of texture_transform(); none for a rotated transform, which -o and -s cannot express.
inline std::optional<MtlPlacement> mtl_placement(const matmaterial::TextureTransform& transform) {
  if (transform.rotation != 0.0) return std::nullopt;
  return MtlPlacement{{transform.offset.x, 1.0 - transform.scale.y - transform.offset.y}, transform.scale};
}

}  // namespace matgeom::obj
