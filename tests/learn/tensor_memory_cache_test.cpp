// The tensor memory cache (matlearn/training/tensor_memory_cache.h): freed buffers serve later
// requests of about their size, small ones and the raw interface oneDNN uses pass through, and
// concurrent use from several threads keeps the books straight. The cache is process-wide and
// other tests use it too, so the checks look at differences of its counters.
#define CATCH_CONFIG_PREFIX_ALL
#include <catch2/catch.hpp>

#include <atomic>
#include <thread>
#include <vector>

#include <c10/core/CPUAllocator.h>

#include "matlearn/training/tensor_memory_cache.h"

using namespace matlearn;

namespace {

constexpr int64_t kMiB = int64_t{1} << 20;

torch::Tensor bytes_tensor(int64_t bytes) { return torch::empty({bytes}, torch::kUInt8); }

}  // namespace

CATCH_TEST_CASE("A freed tensor's memory serves the next request of about its size", "[learn]") {
  use_tensor_memory_cache();
  release_cached_tensor_memory();
  void* first = nullptr;
  {
    torch::Tensor t = bytes_tensor(8 * kMiB);
    first = t.data_ptr();
    t.fill_(7);
  }
  const TensorMemoryCacheStats before = tensor_memory_cache_stats();
  CATCH_CHECK(before.cached_bytes >= static_cast<size_t>(8 * kMiB));
  {
    // 7.5 MiB rounds to 8 MiB: the same block, without asking the system.
    const torch::Tensor again = bytes_tensor(15 * kMiB / 2);
    CATCH_CHECK(again.data_ptr() == first);
    const TensorMemoryCacheStats during = tensor_memory_cache_stats();
    CATCH_CHECK(during.reuses == before.reuses + 1);
    CATCH_CHECK(during.system_allocations == before.system_allocations);
  }
  {
    // Half the size would waste half the free block: a new one.
    const torch::Tensor half = bytes_tensor(4 * kMiB);
    CATCH_CHECK(half.data_ptr() != first);
    CATCH_CHECK(tensor_memory_cache_stats().system_allocations == before.system_allocations + 1);
  }
  // Small tensors go straight to the system and are never cached.
  const size_t cached = tensor_memory_cache_stats().cached_bytes;
  { const torch::Tensor small = bytes_tensor(1000); }
  CATCH_CHECK(tensor_memory_cache_stats().cached_bytes == cached);
  release_cached_tensor_memory();
  CATCH_CHECK(tensor_memory_cache_stats().cached_bytes == 0);
}

CATCH_TEST_CASE("The raw interface oneDNN allocates through round-trips small and large blocks", "[learn]") {
  use_tensor_memory_cache();
  c10::Allocator* allocator = c10::GetAllocator(c10::DeviceType::CPU);
  const size_t in_use = tensor_memory_cache_stats().in_use_bytes;
  void* large = allocator->raw_allocate(3 * kMiB);
  void* small = allocator->raw_allocate(100);
  CATCH_REQUIRE(large != nullptr);
  CATCH_REQUIRE(small != nullptr);
  CATCH_CHECK(reinterpret_cast<uintptr_t>(large) % 64 == 0);  // libtorch's alignment
  CATCH_CHECK(tensor_memory_cache_stats().in_use_bytes == in_use + static_cast<size_t>(3 * kMiB));
  allocator->raw_deallocate(small);
  allocator->raw_deallocate(large);
  CATCH_CHECK(tensor_memory_cache_stats().in_use_bytes == in_use);
}

CATCH_TEST_CASE("Threads allocating and freeing at once leave the books balanced", "[learn]") {
  use_tensor_memory_cache();
  const size_t in_use = tensor_memory_cache_stats().in_use_bytes;
  std::atomic<int> overwritten{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([t, &overwritten] {
      for (int i = 0; i < 200; ++i) {
        torch::Tensor a = bytes_tensor((1 + (i + t) % 5) * kMiB);
        a.fill_(static_cast<uint8_t>(i));
        const torch::Tensor b = bytes_tensor((2 + i % 3) * kMiB / 2);
        if (a[a.numel() - 1].item<uint8_t>() != static_cast<uint8_t>(i)) ++overwritten;
      }
    });
  for (std::thread& t : threads) t.join();
  CATCH_CHECK(overwritten == 0);  // no block was handed to two live tensors
  CATCH_CHECK(tensor_memory_cache_stats().in_use_bytes == in_use);
}
