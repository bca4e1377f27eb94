#pragma once
// Owen-scrambled Sobol points, padded per dimension pair: Burley 2020, "Practical Hash-based
// Owen Scrambling", JCGT 9(4). Each pair of dimensions uses the first two Sobol dimensions
// (a (0,2)-sequence), scrambled and index-shuffled by hashes of (pixel, pair, seed), so every
// pixel's samples depend only on the pixel and the seed: images are identical whatever the
// thread count.
#include <array>
#include <cstdint>

#include <glm/glm.hpp>

namespace matrender {

inline uint32_t reverse_bits(uint32_t x) {
  x = __builtin_bswap32(x);  // bytes, then bits within each byte
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  return ((x >> 4) & 0x0F0F0F0Fu) | ((x & 0x0F0F0F0Fu) << 4);
}

inline uint64_t reverse_bits64(uint64_t x) {
  x = __builtin_bswap64(x);
  x = ((x >> 1) & 0x5555555555555555u) | ((x & 0x5555555555555555u) << 1);
  x = ((x >> 2) & 0x3333333333333333u) | ((x & 0x3333333333333333u) << 2);
  return ((x >> 4) & 0x0F0F0F0F0F0F0F0Fu) | ((x & 0x0F0F0F0F0F0F0F0Fu) << 4);
}

// 32-bit integer hash (Wellons' "lowbias32"): good avalanche, used only to derive seeds.
inline uint32_t hash_u32(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

inline uint32_t hash_combine(uint32_t a, uint32_t b) { return hash_u32(a ^ (hash_u32(b) + 0x9e3779b9u)); }

// Laine-Karras permutation on bit-reversed values: each output bit flips depending only on
// higher-order input bits, i.e. a nested uniform (Owen) scramble (Burley 2020, section 3).
// Word is uint32_t, or a vector of them for lane-parallel use (sample_packet.cpp, which needs
// them inlined so that each instruction set compiles its own copy).
template <typename Word>
[[gnu::always_inline]] inline Word laine_karras_permutation(Word x, uint32_t seed) {
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return x;
}

// First two Sobol dimensions as 32-bit fixed point: van der Corput, and the dimension whose
// generator matrix is Pascal's triangle mod 2 (direction numbers v_k = v_{k-1} ^ (v_{k-1} >> 1)).
inline uint32_t sobol_dimension0(uint32_t index) { return reverse_bits(index); }

// Dimension 1 before its final bit reversal: by Lucas' theorem C(k, j) is odd exactly when the
// bits of j are a subset of those of k, so bit j of the product with Pascal's matrix is the XOR
// of index bits k over all supersets k of j: a superset-sum transform over the five bits of a
// bit position, one shift-and-mask step per bit.
template <typename Word>
[[gnu::always_inline]] inline Word sobol_dimension1_reversed(Word index) {
  index ^= (index >> 1) & 0x55555555u;
  index ^= (index >> 2) & 0x33333333u;
  index ^= (index >> 4) & 0x0F0F0F0Fu;
  index ^= (index >> 8) & 0x00FF00FFu;
  index ^= (index >> 16) & 0x0000FFFFu;
  return index;
}
inline uint32_t sobol_dimension1(uint32_t index) { return reverse_bits(sobol_dimension1_reversed(index)); }

inline float fixed_point_to_unit_float(uint32_t x) {
  // Top 24 bits, so the float is exact and strictly below 1.
  return static_cast<float>(x >> 8) * 0x1p-24f;
}

// The three seeds one dimension pair uses: index shuffle, x scramble, y scramble.
struct PairSeeds {
  uint32_t shuffle = 0, x = 0, y = 0;
  PairSeeds() = default;
  explicit PairSeeds(uint32_t seed)
      : shuffle(hash_combine(seed, 0xa511e9b3u)),
        x(hash_combine(seed, 0x63d83595u)),
        y(hash_combine(seed, 0x1b873593u)) {}
};

// 2-D point of the scrambled sequence with the given seeds, for the sample whose index reversed
// is `reversed_index` (every pair of a sample shares it). The index is shuffled by a nested
// uniform scramble, shuffled = reverse_bits(laine_karras_permutation(reverse_bits(index))), and
// both coordinates are nested_uniform_scramble(reverse_bits(r), seed) =
// reverse_bits(laine_karras_permutation(r, seed)) for r = shuffled and
// r = sobol_dimension1_reversed(shuffled): the inner reversals cancel.
// The Sobol index a sample takes in a dimension pair: its own index, nested-uniform shuffled.
inline uint32_t shuffled_sobol_index(uint32_t reversed_index, const PairSeeds& seeds) {
  return reverse_bits(laine_karras_permutation(reversed_index, seeds.shuffle));
}

inline glm::vec2 owen_sobol_2d_reversed_index(uint32_t reversed_index, const PairSeeds& seeds) {
  const uint32_t shuffled = shuffled_sobol_index(reversed_index, seeds);
  const uint32_t x_reversed = laine_karras_permutation(shuffled, seeds.x);
  const uint32_t y_reversed = laine_karras_permutation(sobol_dimension1_reversed(shuffled), seeds.y);
  // Both reversals in one 64-bit reversal: it swaps the halves and reverses each.
  const uint64_t xy = reverse_bits64((uint64_t{y_reversed} << 32) | x_reversed);
  return {fixed_point_to_unit_float(static_cast<uint32_t>(xy >> 32)), fixed_point_to_unit_float(static_cast<uint32_t>(xy))};
}

// Seeds of every dimension pair of one pixel. They do not depend on the sample index, so all
// samples of the pixel share them; the first kCachedPairs are derived on first use and kept.
class PixelSeeds {
 public:
  PixelSeeds(uint32_t pixel_index, uint32_t global_seed)
      : pixel_seed_(hash_combine(hash_u32(pixel_index), global_seed)) {}

  PairSeeds pair(uint32_t k) const {
    if (k >= kCachedPairs) return PairSeeds(hash_combine(pixel_seed_, k));
    if (!(filled_ >> k & 1u)) {
      cache_[k] = PairSeeds(hash_combine(pixel_seed_, k));
      filled_ |= uint64_t{1} << k;
    }
    return cache_[k];
  }

 private:
  static constexpr uint32_t kCachedPairs = 64;
  uint32_t pixel_seed_;
  mutable uint64_t filled_ = 0;
  mutable std::array<PairSeeds, kCachedPairs> cache_;
};

}  // namespace matrender
