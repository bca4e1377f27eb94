#pragma once
// A caching CPU allocator for libtorch. A training step allocates and frees the same large
// activation and gradient buffers in the same order every step. Through glibc each buffer over
// its mmap threshold (at most 32 MiB) is a fresh mmap whose pages the kernel faults in and zeroes
// on first touch, then a munmap: at batch 8 and 224 px that is about a quarter of a ResNet
// step's CPU time in the kernel. Kept here instead, a freed buffer serves the next request of
// about its size without a system call, as PyTorch's CUDA caching allocator does on the GPU.
#include <cstddef>

namespace matlearn {

struct TensorMemoryCacheStats {
  size_t cached_bytes = 0;   // held for reuse, not in any tensor
  size_t in_use_bytes = 0;   // in live allocations made through the cache
  size_t reuses = 0;         // requests served from the cache
  size_t system_allocations = 0;
};

// Makes the cache libtorch's CPU allocator for the rest of the process (tensors allocated before
// keep their own deleters). Calling it again does nothing.
void use_tensor_memory_cache();

TensorMemoryCacheStats tensor_memory_cache_stats();

// Returns every cached block to the system (between jobs of different shapes).
void release_cached_tensor_memory();

}  // namespace matlearn
