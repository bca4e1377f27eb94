#pragma once
// Seeds and uniform numbers that are the same on every platform and standard library (whose
// distributions are not): SplitMix64 (Steele, Lea and Flood 2014, "Fast splittable pseudorandom
// number generators"), its finaliser to mix indices into seeds and its sequence as a stream.
#include <cstdint>

namespace matdataset {

// SplitMix64's step and finaliser, a bijection: seeds mixed from neighbouring indices differ in
// every bit.
inline uint64_t splitmix64(uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

class SeedStream {
 public:
  explicit SeedStream(uint64_t seed) : state_(seed) {}
  uint64_t next() {
    const uint64_t out = splitmix64(state_);
    state_ += 0x9e3779b97f4a7c15ull;
    return out;
  }
  // Uniform on [0, 1): the top 53 bits.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

 private:
  uint64_t state_;
};

}  // namespace matdataset
