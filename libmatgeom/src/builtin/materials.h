#pragma once
// The built-in objects' materials: a finish (wood, fabric, ...) is a material of the procedural
// library (matmaterial/library/material_library.h), its style and seed drawn from the object's random
// numbers where the finish leaves them open.
#include <string>

#include "matbase/uniform_source.h"
#include "matgeom/object_asset.h"

namespace matgeom::builtin {

enum class Finish {
  Wood,          // raw or lacquered timber: wood/raw, wood/lacquered
  PaintedWood,   // wood/painted
  Fabric,        // any fabric style: plain weave, twill, velvet
  Leather,       // pebbled or smooth
  BrushedMetal,  // metal/brushed
  Plastic,       // plastic/glossy: constants, no images
  Ceramic,       // glazed or speckled, under a clearcoat
  Concrete,      // concrete/cast
  Paper,         // paper/sheet
  Wicker,        // wood/wicker
};

// Texels along each side of a built-in material's maps, and of the UV pass's tiles.
constexpr int kBuiltinTextureSize = 256;
constexpr int kBuiltinTileResolution = 1024;

struct BuiltinMaterial {
  matmaterial::MaterialInputs material;  // named after its slot; its images appended to the asset's
  double tile_size_m = 1.0;  // how long one repeat of its maps is (the UV pass's UVs scale them)
};

// Appends the material's images to asset.images and returns the material, named `slot`.
BuiltinMaterial make_material(ObjectAsset& asset, const std::string& slot, Finish finish, matbase::UniformSource& random);

}  // namespace matgeom::builtin
