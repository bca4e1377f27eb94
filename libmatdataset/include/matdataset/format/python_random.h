#pragma once
// Python's random.Random, as far as its shuffle: the Mersenne Twister MT19937 (Matsumoto and
// Nishimura 1998) seeded from an integer the way CPython seeds it (init_by_array over the
// integer's 32-bit words, least significant first), getrandbits, _randbelow's rejection
// sampling and shuffle's Fisher-Yates order (CPython 3.11, Lib/random.py). With it the
// repository's seeded splits (generate_splits.py: random.Random(42).shuffle) come out the same
// here, sample for sample.
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace matdataset {

class PythonRandom {
 public:
  explicit PythonRandom(uint64_t seed);

  // The next 32-bit output of MT19937 (genrand_uint32).
  uint32_t next_uint32();
  // random.getrandbits(k), 1 <= k <= 64: the first 32-bit word is the least significant.
  uint64_t getrandbits(int k);
  // random._randbelow(n), n >= 1: getrandbits(n.bit_length()) until below n.
  uint64_t randbelow(uint64_t n);

  // random.shuffle(items).
  template <typename T>
  void shuffle(std::vector<T>& items) {
    for (size_t i = items.size(); i-- > 1;) std::swap(items[i], items[static_cast<size_t>(randbelow(i + 1))]);
  }

 private:
  static constexpr int kStateSize = 624;
  void twist();
  std::array<uint32_t, kStateSize> state_{};
  int index_ = kStateSize;
};

}  // namespace matdataset
