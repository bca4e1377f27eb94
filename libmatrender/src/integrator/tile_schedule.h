#pragma once
// The image in tiles of 16 x 16 pixels, rendered a tile per task on the render's worker threads.
// Tiles are handed out one at a time (simple_partitioner): most of a frame's cost sits in the few
// tiles the object covers, since pixels that cannot see it take no rays, and TBB's default chunks
// of tiles left one thread finishing alone (the textured vase at 64 spp: 1.72 x one thread's
// speed on 2 threads, 1.80 x with single tiles; render_bench). What a pixel gets never depends on
// which thread renders it.
#include <cstddef>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

namespace matrender {

struct Tile {
  int x0, y0, x1, y1;  // pixels [x0, x1) x [y0, y1)
};

// Tiles of kTileSize covering width x height pixels, row by row; the last in a row or column
// may be smaller.
constexpr int kTileSize = 16;
std::vector<Tile> image_tiles(int width, int height);

class TileSchedule {
 public:
  // threads: as RenderSettings::threads (0: all hardware threads).
  TileSchedule(int width, int height, int threads);

  const std::vector<Tile>& tiles() const { return tiles_; }

  // Calls visit(index, tile) once for every tile, from the worker threads, until stop() is true;
  // tiles not begun by then are skipped.
  template <class Stop, class Visit>
  void run(Stop&& stop, Visit&& visit) {
    arena_.execute([&] {
      tbb::parallel_for(
          tbb::blocked_range<size_t>(0, tiles_.size(), 1),
          [&](const tbb::blocked_range<size_t>& range) {
            for (size_t t = range.begin(); t != range.end(); ++t) {
              if (stop()) return;
              visit(t, tiles_[t]);
            }
          },
          tbb::simple_partitioner());
    });
  }

 private:
  std::vector<Tile> tiles_;
  tbb::task_arena arena_;
};

}  // namespace matrender
