#include "texture/texel_cache.h"

#include <algorithm>
#include <atomic>
#include <memory>
#include <vector>

#include "matbase/memory_limit.h"
#include "matrender/texture_cache.h"

namespace matrender {

// The process-wide state behind TexelPage. Never destroyed: textures in static objects may
// outlive any static cache, and threads' pins end after main returns.
struct TexelCache {
  std::mutex mutex;
  std::vector<TexelPage*> held;  // the pages whose texels the cache holds
  uint64_t held_bytes = 0;
  uint64_t clock = 0;            // advances at every acquire: the pages' last_use_
  uint64_t limit_bytes = 0;      // 0: the default
  std::atomic<uint64_t> resident_bytes{0}, peak_bytes{0}, evictions{0}, reloads{0};
  std::atomic<uint64_t> next_page_id{1};

  static TexelCache& instance() {
    static TexelCache* cache = new TexelCache;
    return *cache;
  }

  uint64_t limit() const { return limit_bytes != 0 ? limit_bytes : default_texture_memory_limit(); }

  void count_allocation(uint64_t bytes) {
    const uint64_t now = resident_bytes.fetch_add(bytes) + bytes;
    uint64_t peak = peak_bytes.load();
    while (now > peak && !peak_bytes.compare_exchange_weak(peak, now)) {
    }
  }

  // With the mutex held: `page` now holds `texels`, used now (a lookup) or never (a source).
  void hold(TexelPage& page, std::shared_ptr<const TexelLevel> texels, TexelPage::Use use) {
    held_bytes += texels->memory_bytes();
    page.texels_ = std::move(texels);
    page.last_use_ = use == TexelPage::Use::Lookup ? ++clock : 0;
    held.push_back(&page);
  }

  // With the mutex held: the cache no longer holds the page's texels (freed once no thread pins them).
  void drop(TexelPage& page) {
    const auto it = std::find(held.begin(), held.end(), &page);
    if (it == held.end()) return;
    held_bytes -= page.texels_->memory_bytes();
    page.texels_.reset();
    *it = held.back();
    held.pop_back();
  }

  // With the mutex held: drops the least recently used pages, never `keep`, until the held
  // texels fit the limit or nothing else can go.
  void evict_over_limit(const TexelPage* keep) {
    while (held_bytes > limit()) {
      TexelPage* victim = nullptr;
      for (TexelPage* page : held)
        if (page != keep && page->evictable_ && (!victim || page->last_use_ < victim->last_use_)) victim = page;
      if (!victim) return;
      drop(*victim);
      ++evictions;
    }
  }
};

TexelPage::TexelPage(std::function<TexelLevel()> make, bool evictable)
    : id_(TexelCache::instance().next_page_id++), make_(std::move(make)), evictable_(evictable) {}

TexelPage::~TexelPage() {
  TexelCache& cache = TexelCache::instance();
  std::lock_guard<std::mutex> lock(cache.mutex);
  if (texels_) cache.drop(*this);
}

std::shared_ptr<const TexelLevel> TexelPage::publish(TexelLevel texels) {
  TexelCache& cache = TexelCache::instance();
  const uint64_t bytes = texels.memory_bytes();
  cache.count_allocation(bytes);
  return std::shared_ptr<const TexelLevel>(new TexelLevel(std::move(texels)), [bytes](const TexelLevel* level) {
    TexelCache::instance().resident_bytes -= bytes;
    delete level;
  });
}

void TexelPage::install(TexelLevel texels) {
  std::lock_guard<std::mutex> making(make_mutex_);
  std::shared_ptr<const TexelLevel> published = publish(std::move(texels));
  TexelCache& cache = TexelCache::instance();
  std::lock_guard<std::mutex> lock(cache.mutex);
  if (texels_) cache.drop(*this);
  made_before_ = true;
  cache.hold(*this, std::move(published), Use::Lookup);
  cache.evict_over_limit(this);
}

std::shared_ptr<const TexelLevel> TexelPage::acquire(Use use) {
  TexelCache& cache = TexelCache::instance();
  const auto held_texels = [&]() -> std::shared_ptr<const TexelLevel> {
    std::lock_guard<std::mutex> lock(cache.mutex);
    if (texels_ && use == Use::Lookup) last_use_ = ++cache.clock;
    return texels_;
  };
  if (auto texels = held_texels()) return texels;
  std::lock_guard<std::mutex> making(make_mutex_);
  if (auto texels = held_texels()) return texels;  // another thread made them meanwhile
  std::shared_ptr<const TexelLevel> made = publish(make_());
  std::lock_guard<std::mutex> lock(cache.mutex);
  if (made_before_) ++cache.reloads;
  made_before_ = true;
  cache.hold(*this, made, use);
  cache.evict_over_limit(this);
  return made;
}

namespace {

// A thread's pinned pages, direct-mapped by id: pages are numbered as they are made, so a
// texture's levels, and the textures of one material, fall in different slots. Replacing pins
// in turn instead made a textured material's trilinear lookups (three maps, two levels each)
// miss at 18 % of lookups on the textured vase, and every miss locks the cache's mutex, which
// the threads share.
struct Pins {
  uint64_t ids[kPinnedPages] = {};
  std::shared_ptr<const TexelLevel> texels[kPinnedPages];
};
// Lookups reach the pins through a plain pointer: a thread_local with a destructor costs every
// access a second TLS lookup, for its guard, and pinning inline made the lookup save registers
// (52 instructions a lookup on the textured vase, 27 now). The pins are freed at the thread's
// exit by owned_pins.
thread_local Pins* thread_pins = nullptr;
thread_local std::unique_ptr<Pins> owned_pins;

[[gnu::noinline]] const TexelLevel& pin(TexelPage& page, size_t slot) {
  if (!thread_pins) {
    owned_pins = std::make_unique<Pins>();
    thread_pins = owned_pins.get();
  }
  Pins& p = *thread_pins;
  p.texels[slot] = page.acquire();
  p.ids[slot] = page.id();
  return *p.texels[slot];
}

}  // namespace

const TexelLevel& pinned_texels(TexelPage& page) {
  const Pins* p = thread_pins;
  const uint64_t id = page.id();
  const size_t slot = id % kPinnedPages;
  if (p && p->ids[slot] == id) return *p->texels[slot];
  return pin(page, slot);
}

void release_pinned_texels() {
  Pins* p = thread_pins;
  if (!p) return;
  for (size_t i = 0; i < kPinnedPages; ++i) {
    p->ids[i] = 0;
    p->texels[i].reset();
  }
}

uint64_t default_texture_memory_limit() {
  static const uint64_t limit = matbase::memory_limit_bytes() / 2;
  return limit;
}

void set_texture_memory_limit(uint64_t bytes) {
  TexelCache& cache = TexelCache::instance();
  std::lock_guard<std::mutex> lock(cache.mutex);
  cache.limit_bytes = bytes;
  cache.evict_over_limit(nullptr);
}

TextureCacheStats texture_cache_stats() {
  TexelCache& cache = TexelCache::instance();
  std::lock_guard<std::mutex> lock(cache.mutex);
  return {cache.limit(), cache.resident_bytes.load(), cache.peak_bytes.load(), cache.evictions.load(),
          cache.reloads.load()};
}

void reset_texture_cache_counters() {
  TexelCache& cache = TexelCache::instance();
  std::lock_guard<std::mutex> lock(cache.mutex);
  cache.peak_bytes = cache.resident_bytes.load();
  cache.evictions = 0;
  cache.reloads = 0;
}

}  // namespace matrender
