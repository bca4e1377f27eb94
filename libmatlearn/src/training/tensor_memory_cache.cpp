#include "matlearn/training/tensor_memory_cache.h"

#include <map>
#include <mutex>
#include <unordered_map>

#include <c10/core/CPUAllocator.h>
#include <c10/core/impl/alloc_cpu.h>

namespace matlearn {
namespace {

// Below this glibc serves requests from its heap without system calls: not worth caching.
constexpr size_t kSmallestCached = size_t{256} << 10;
// Cached sizes are rounded up to this, so that buffers of nearly equal size share blocks.
constexpr size_t kGranule = size_t{1} << 20;
// A cached block serves requests down to 1/(1 + 1/8) of its size: at most 12.5 % is wasted.
constexpr size_t kWasteDivisor = 8;

size_t rounded_size(size_t bytes) { return (bytes + kGranule - 1) / kGranule * kGranule; }

class BlockCache {
 public:
  static BlockCache& instance() {
    static BlockCache* cache = new BlockCache;  // never destroyed: tensors may outlive statics
    return *cache;
  }

  void* take(size_t bytes) {
    const size_t size = rounded_size(bytes);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      const auto fit = free_.lower_bound(size);
      if (fit != free_.end() && fit->first <= size + size / kWasteDivisor) {
        void* data = fit->second;
        in_use_.emplace(data, fit->first);
        stats_.cached_bytes -= fit->first;
        stats_.in_use_bytes += fit->first;
        ++stats_.reuses;
        free_.erase(fit);
        return data;
      }
    }
    void* data = allocate_from_system(size);
    std::lock_guard<std::mutex> lock(mutex_);
    in_use_.emplace(data, size);
    stats_.in_use_bytes += size;
    ++stats_.system_allocations;
    return data;
  }

  // False when `data` did not come from take().
  bool give_back(void* data) {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto block = in_use_.find(data);
    if (block == in_use_.end()) return false;
    free_.emplace(block->second, data);
    stats_.in_use_bytes -= block->second;
    stats_.cached_bytes += block->second;
    in_use_.erase(block);
    return true;
  }

  void release_all() {
    std::multimap<size_t, void*> released;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      released.swap(free_);
      stats_.cached_bytes = 0;
    }
    for (const auto& block : released) c10::free_cpu(block.second);
  }

  TensorMemoryCacheStats stats() {
    std::lock_guard<std::mutex> lock(mutex_);
    return stats_;
  }

 private:
  // When the system has no memory left, the cache gives its blocks back and tries once more.
  void* allocate_from_system(size_t size) {
    try {
      return c10::alloc_cpu(size);
    } catch (const c10::Error&) {
      release_all();
      return c10::alloc_cpu(size);
    }
  }

  std::mutex mutex_;
  std::multimap<size_t, void*> free_;          // cached blocks by size
  std::unordered_map<void*, size_t> in_use_;   // blocks handed out, with their sizes
  TensorMemoryCacheStats stats_;
};

void release_block(void* data) {
  if (!BlockCache::instance().give_back(data)) c10::free_cpu(data);
}

class CachingCpuAllocator final : public c10::Allocator {
 public:
  c10::DataPtr allocate(size_t bytes) const override {
    const c10::Device cpu(c10::DeviceType::CPU);
    if (bytes < kSmallestCached) {
      void* data = c10::alloc_cpu(bytes);
      return {data, data, &c10::free_cpu, cpu};
    }
    void* data = BlockCache::instance().take(bytes);
    return {data, data, &release_block, cpu};
  }
  // raw_deallocate passes every pointer here, small ones included: release_block tells them apart.
  c10::DeleterFnPtr raw_deleter() const override { return &release_block; }
};

}  // namespace

void use_tensor_memory_cache() {
  static CachingCpuAllocator allocator;
  static std::once_flag installed;
  // Priority 1 outranks libtorch's default allocator, registered at 0.
  std::call_once(installed, [] { c10::SetCPUAllocator(&allocator, 1); });
}

TensorMemoryCacheStats tensor_memory_cache_stats() { return BlockCache::instance().stats(); }

void release_cached_tensor_memory() { BlockCache::instance().release_all(); }

}  // namespace matlearn
