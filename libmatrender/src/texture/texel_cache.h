#pragma once
// The entries of the texture cache (matrender/texture_cache.h): a TexelPage is one level of one
// texture, in memory or not. Lookups pin the levels they read, per thread, so that a level the
// cache drops stays valid until the pinning thread lets it go.
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>

#include "texture/texel_level.h"

namespace matrender {

class TexelPage {
 public:
  // `make` makes the level's texels when a lookup needs them and they are not in memory; it may
  // acquire other pages (a mip level its finer level). A page that is not `evictable` stays once
  // made or installed.
  TexelPage(std::function<TexelLevel()> make, bool evictable);
  ~TexelPage();
  TexelPage(const TexelPage&) = delete;
  TexelPage& operator=(const TexelPage&) = delete;

  // Texels already made (a texture's level 0 as it is loaded) go into the cache.
  void install(TexelLevel texels);
  // The level's texels, made first if they are not in memory. Thread safe. A lookup's acquire
  // makes the level the most recently used; a `source` acquire (the finer level a mip level is
  // filtered from) leaves it, or makes it the least recently used: otherwise a big level 0
  // decoded to make one small level would push other textures' small levels out.
  enum class Use { Lookup, Source };
  std::shared_ptr<const TexelLevel> acquire(Use use = Use::Lookup);
  // Unique for the life of the process (never reused, unlike an address).
  uint64_t id() const { return id_; }

 private:
  friend struct TexelCache;
  std::shared_ptr<const TexelLevel> publish(TexelLevel texels);
  const uint64_t id_;
  const std::function<TexelLevel()> make_;
  const bool evictable_;
  std::mutex make_mutex_;  // one thread makes the level, the others wait for it
  // Guarded by the cache's mutex.
  std::shared_ptr<const TexelLevel> texels_;
  uint64_t last_use_ = 0;
  bool made_before_ = false;
};

// The page's texels, pinned by this thread: valid until this thread pins another page or calls
// release_pinned_texels(). A thread keeps at most kPinnedPages pins.
constexpr size_t kPinnedPages = 32;
const TexelLevel& pinned_texels(TexelPage& page);
// Lets go of this thread's pins (the renderer, after each tile).
void release_pinned_texels();

}  // namespace matrender
