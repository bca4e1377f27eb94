#pragma once
// Turns a recipe into the maps of a material folder at a chosen resolution.
#include <atomic>
#include <string>

#include "library/recipe.h"
#include "matmaterial/folder/material_folder.h"

namespace matmaterial::library {

// Samples the recipe at the centres of resolution x resolution texels (rows top to bottom) on
// up to `threads` threads (matbase::worker_threads); the bytes do not depend on the count.
// A map whose texels are all equal becomes a constant, not an image. The normal map is the
// slope of the relief at the tile's physical size (central differences across the wrap), the
// height map that relief normalised to [0, 1]; neither is written for a flat recipe.
// `tile_size_m` is the length the tile covers on a surface (MatSynth's physical size). Throws
// Cancelled within a row of `cancel` (when given) being set.
FolderMaterial rasterise_recipe(const Recipe& recipe, const std::string& name, MaterialClass material_class,
                                double tile_size_m, int resolution, int threads, const std::atomic<bool>* cancel);

}  // namespace matmaterial::library
