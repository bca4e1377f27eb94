#pragma once
// The procedural library's styles: each draws its colours, scales and patterns from `random`
// and returns the recipe of one material. Listed, with their classes and descriptions, in
// material_library.cpp's table.
#include "library/recipe.h"
#include "matbase/uniform_source.h"

namespace matmaterial::library {

// Organic (organic_styles.cpp).
Recipe raw_wood(matbase::UniformSource& random);
Recipe lacquered_wood(matbase::UniformSource& random);
Recipe painted_wood(matbase::UniformSource& random);
Recipe wicker(matbase::UniformSource& random);
Recipe plain_weave_fabric(matbase::UniformSource& random);
Recipe twill_fabric(matbase::UniformSource& random);
Recipe velvet_fabric(matbase::UniformSource& random);
Recipe pebbled_leather(matbase::UniformSource& random);
Recipe smooth_leather(matbase::UniformSource& random);
Recipe paper_sheet(matbase::UniformSource& random);
Recipe corrugated_cardboard(matbase::UniformSource& random);
Recipe perforated_paper(matbase::UniformSource& random);

// Mineral (mineral_styles.cpp).
Recipe cast_concrete(matbase::UniformSource& random);
Recipe aggregate_concrete(matbase::UniformSource& random);
Recipe granite(matbase::UniformSource& random);
Recipe slate(matbase::UniformSource& random);
Recipe sandstone(matbase::UniformSource& random);
Recipe carrara_marble(matbase::UniformSource& random);
Recipe nero_marble(matbase::UniformSource& random);
Recipe glazed_ceramic(matbase::UniformSource& random);
Recipe speckled_ceramic(matbase::UniformSource& random);
Recipe terracotta(matbase::UniformSource& random);
Recipe trowelled_plaster(matbase::UniformSource& random);

// Manufactured (manufactured_styles.cpp).
Recipe glossy_plastic(matbase::UniformSource& random);
Recipe matte_plastic(matbase::UniformSource& random);
Recipe textured_plastic(matbase::UniformSource& random);
Recipe matte_rubber(matbase::UniformSource& random);
Recipe ribbed_rubber(matbase::UniformSource& random);
Recipe brushed_metal(matbase::UniformSource& random);
Recipe polished_metal(matbase::UniformSource& random);
Recipe hammered_metal(matbase::UniformSource& random);
Recipe perforated_metal(matbase::UniformSource& random);
Recipe clear_glass(matbase::UniformSource& random);
Recipe tinted_glass(matbase::UniformSource& random);
Recipe frosted_glass(matbase::UniformSource& random);

}  // namespace matmaterial::library
