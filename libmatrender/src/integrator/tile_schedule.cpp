#include "integrator/tile_schedule.h"

#include <algorithm>

#include "matbase/threads.h"

namespace matrender {

std::vector<Tile> image_tiles(int width, int height) {
  std::vector<Tile> tiles;
  for (int y = 0; y < height; y += kTileSize)
    for (int x = 0; x < width; x += kTileSize)
      tiles.push_back({x, y, std::min(x + kTileSize, width), std::min(y + kTileSize, height)});
  return tiles;
}

TileSchedule::TileSchedule(int width, int height, int threads)
    : tiles_(image_tiles(width, height)), arena_(matbase::worker_threads(threads)) {}

}  // namespace matrender
