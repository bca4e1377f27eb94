#include "matgeom/uv/uv_packing.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

namespace matgeom {
namespace {

// Shelf packing in `order` with shelves at most `shelf_width` pixels wide (gutters included):
// rectangles fill a shelf left to right, shelves stack bottom to top, a tile is closed when the
// next shelf does not fit.
Packing shelf_pack(const std::vector<glm::ivec2>& sizes, const std::vector<size_t>& order, int shelf_width,
                   const PackingOptions& options) {
  const int resolution = options.tile_resolution, gutter = options.gutter_pixels;
  Packing packing;
  packing.rectangles.resize(sizes.size());
  if (sizes.empty()) return packing;
  packing.tiles = 1;
  int x = gutter, shelf_y = gutter, shelf_height = 0, right_edge = 0;
  for (const size_t i : order) {
    const glm::ivec2 size = sizes[i];
    if (x + size.x + gutter > shelf_width) {  // next shelf
      x = gutter;
      shelf_y += shelf_height + gutter;
      shelf_height = 0;
    }
    if (shelf_y + size.y + gutter > resolution) {  // next tile
      ++packing.tiles;
      right_edge = 0;
      x = gutter;
      shelf_y = gutter;
      shelf_height = 0;
    }
    packing.rectangles[i] = {packing.tiles - 1, glm::ivec2(x, shelf_y)};
    x += size.x + gutter;
    right_edge = std::max(right_edge, x);
    shelf_height = std::max(shelf_height, size.y);
  }
  packing.last_tile_width = right_edge;
  packing.last_tile_height = shelf_y + shelf_height + gutter;
  return packing;
}

double occupied_area(const Packing& packing, int resolution) {
  return (packing.tiles - 1.0) * resolution * resolution +
         static_cast<double>(packing.last_tile_width) * packing.last_tile_height;
}

}  // namespace

Packing pack_rectangles(const std::vector<glm::ivec2>& sizes, const PackingOptions& options) {
  const int resolution = options.tile_resolution, gutter = options.gutter_pixels;
  if (resolution < 1 || gutter < 0 || resolution <= 2 * gutter)
    throw std::invalid_argument("pack_rectangles: tile resolution " + std::to_string(resolution) +
                                " leaves no room inside gutters of " + std::to_string(gutter) + " pixels");
  const int usable = resolution - 2 * gutter;
  double padded_area = 0.0;
  int widest = 0;
  for (size_t i = 0; i < sizes.size(); ++i) {
    if (sizes[i].x < 1 || sizes[i].y < 1 || sizes[i].x > usable || sizes[i].y > usable)
      throw std::invalid_argument("pack_rectangles: rectangle " + std::to_string(i) + " (" +
                                  std::to_string(sizes[i].x) + " x " + std::to_string(sizes[i].y) +
                                  " pixels) does not fit in a tile of " + std::to_string(resolution) +
                                  " pixels with its gutters");
    padded_area += static_cast<double>(sizes[i].x + gutter) * (sizes[i].y + gutter);
    widest = std::max(widest, sizes[i].x);
  }
  std::vector<size_t> order(sizes.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return sizes[a].y > sizes[b].y; });

  // Full-width shelves, then narrower ones from the side of a square holding every rectangle
  // up, 10% wider each time: the fewest tiles, then the least occupied area wins.
  Packing best = shelf_pack(sizes, order, resolution, options);
  const double first_width = std::max<double>(widest + 2 * gutter, std::sqrt(padded_area) + gutter);
  for (double width = first_width; width < resolution; width *= 1.1) {
    Packing candidate = shelf_pack(sizes, order, static_cast<int>(std::ceil(width)), options);
    if (candidate.tiles < best.tiles ||
        (candidate.tiles == best.tiles && occupied_area(candidate, resolution) < occupied_area(best, resolution)))
      best = std::move(candidate);
  }
  return best;
}

}  // namespace matgeom
