#pragma once
// Every texture's texels live in one process-wide cache with a memory bound, as OpenImageIO's
// TextureSystem keeps its tiles: a scene with dozens of 4k maps renders in the memory its
// lookups need, not the memory all its maps would take. The cache holds each mip level of each
// texture (and each UDIM tile's) as one entry. When the entries it holds pass the limit it drops
// the least recently used ones, and makes them again if a lookup needs them later: a dropped
// level 0 is decoded from its file again, a dropped mip level filtered again from the finer one.
// Textures made from pixels in memory keep their level 0 (there is nothing to make it again from).
//
// The limit holds between render tiles: a thread keeps the few levels it is looking up in until
// its tile ends, and they are freed then if the cache has dropped them. With a limit below what
// one view needs, files are decoded again and again (`reloads` counts it): rendering slows down
// but gives the same pixels.
#include <cstdint>

namespace matrender {

struct TextureCacheStats {
  uint64_t limit_bytes = 0;     // the bound in force
  uint64_t resident_bytes = 0;  // texels in memory now
  uint64_t peak_bytes = 0;      // the most texels in memory at once since the last reset
  uint64_t evictions = 0;       // levels dropped to stay within the limit
  uint64_t reloads = 0;         // levels made again after being dropped
};

// Half of the memory this process can have (matbase::memory_limit_bytes): dozens of 4k maps
// with their mip levels fit on a 16 GiB machine without anything being dropped.
uint64_t default_texture_memory_limit();
// 0 restores the default. A lower limit drops what no longer fits at once.
void set_texture_memory_limit(uint64_t bytes);

TextureCacheStats texture_cache_stats();
// Starts a new peak from what is resident now (and zeroes the eviction and reload counts).
void reset_texture_cache_counters();

}  // namespace matrender
