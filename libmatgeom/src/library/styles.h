#pragma once
// The procedural library's styles: each draws its colours, scales and patterns from `random`
// and returns the recipe of one material. Listed, with their classes and descriptions, in
// material_library.cpp's table.
#include "library/recipe.h"
#include "uniform_source.h"

namespace matgeom::library {

// Organic (organic_styles.cpp).
Recipe raw_wood(UniformSource& random);
Recipe lacquered_wood(UniformSource& random);
Recipe painted_wood(UniformSource& random);
Recipe wicker(UniformSource& random);
Recipe plain_weave_fabric(UniformSource& random);
Recipe twill_fabric(UniformSource& random);
Recipe velvet_fabric(UniformSource& random);
Recipe pebbled_leather(UniformSource& random);
Recipe smooth_leather(UniformSource& random);
Recipe paper_sheet(UniformSource& random);
Recipe corrugated_cardboard(UniformSource& random);
Recipe perforated_paper(UniformSource& random);

// Mineral (mineral_styles.cpp).
Recipe cast_concrete(UniformSource& random);
Recipe aggregate_concrete(UniformSource& random);
Recipe granite(UniformSource& random);
Recipe slate(UniformSource& random);
Recipe sandstone(UniformSource& random);
Recipe carrara_marble(UniformSource& random);
Recipe nero_marble(UniformSource& random);
Recipe glazed_ceramic(UniformSource& random);
Recipe speckled_ceramic(UniformSource& random);
Recipe terracotta(UniformSource& random);
Recipe trowelled_plaster(UniformSource& random);

// Manufactured (manufactured_styles.cpp).
Recipe glossy_plastic(UniformSource& random);
Recipe matte_plastic(UniformSource& random);
Recipe textured_plastic(UniformSource& random);
Recipe matte_rubber(UniformSource& random);
Recipe ribbed_rubber(UniformSource& random);
Recipe brushed_metal(UniformSource& random);
Recipe polished_metal(UniformSource& random);
Recipe hammered_metal(UniformSource& random);
Recipe perforated_metal(UniformSource& random);
Recipe clear_glass(UniformSource& random);
Recipe tinted_glass(UniformSource& random);
Recipe frosted_glass(UniformSource& random);

}  // namespace matgeom::library
