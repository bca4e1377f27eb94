#pragma once
// Greedy packing of chart rectangles into UDIM tiles: tile k covers u in [k, k + 1), v in [0, 1).
#include <vector>

#include <glm/glm.hpp>

namespace matgeom {

struct PackingOptions {
  int tile_resolution = 4096;  // pixels along each side of a tile
  int gutter_pixels = 2;       // free pixels between rectangles and along the tile edges
};

struct PackedRectangle {
  int tile = 0;
  glm::ivec2 origin{0};  // lower-left pixel inside the tile
};

struct Packing {
  std::vector<PackedRectangle> rectangles;  // in the order of the input sizes
  int tiles = 0;
  // The part of the last tile in use: up to the right edge of its rightmost rectangle and the
  // top of its highest, plus the gutter.
  int last_tile_width = 0, last_tile_height = 0;
};

// Shelf packing, tallest first (ties by input order): rectangles fill a shelf left to right and
// shelves stack bottom to top; a tile is closed when the next shelf does not fit. Shelves narrower
// than the tile are tried too, and the packing with the fewest tiles and then the smallest used
// area of the last tile is kept, so that a few charts fill a dense corner rather than one long,
// mostly empty strip. Every rectangle keeps gutter_pixels to its neighbours and to the tile edges. Throws
// std::invalid_argument when a size is not positive or does not fit in a tile with its gutters.
Packing pack_rectangles(const std::vector<glm::ivec2>& sizes, const PackingOptions& options);

}  // namespace matgeom
