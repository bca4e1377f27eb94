#pragma once
// The built-in materials: a finish (wood, fabric, ...) becomes a MaterialDesc with seeded,
// tileable texture images, labelled with its class (matgeom/material_classes.h).
#include <string>

#include "uniform_source.h"
#include "matgeom/object_asset.h"

namespace matgeom::builtin {

enum class Finish {
  Wood,          // grain rings, varnished: wood
  PaintedWood,   // flat colour, satin: wood
  Fabric,        // woven threads: fabric
  Leather,       // pebbled grain: leather
  BrushedMetal,  // streaks along u, metallic: metal
  Plastic,       // flat colour, constant parameters (no images): plastic
  Ceramic,       // mottled glaze: ceramic
  Concrete,      // speckled, rough: concrete
  Paper,         // fine fibres: paper
  Wicker,        // woven strands: wood
};

// Texels per UV unit of the built-in images (tileable, repeated across UDIM tiles). The objects'
// UV pass uses 1024-pixel tiles, so an object's charts, sqrt(512^2 pi) ~ 900 px across in all at
// s = 1, span about one UV unit, and one image covers about the whole object.
constexpr int kBuiltinTextureSize = 256;
constexpr int kBuiltinTileResolution = 1024;

// Appends the material's images to asset.images and returns the material, named `slot`.
// Colours and texture patterns vary with `random`.
MaterialDesc make_material(ObjectAsset& asset, const std::string& slot, Finish finish, UniformSource& random);

}  // namespace matgeom::builtin
