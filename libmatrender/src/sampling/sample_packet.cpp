// 64-byte vectors below never cross a call between functions of different targets, so the
// warning that their calling convention differs by target does not apply (see Words).
#pragma GCC diagnostic ignored "-Wpsabi"

#include "sampling/sample_packet.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace matrender {
namespace {

// One 32-bit word per sample of the packet. GCC and Clang split each operation into the
// registers the function's target has: four SSE2, two AVX2 or one AVX-512 register(s). Such
// wide vectors are never passed between functions of different targets (their calling
// convention differs): everything below is inlined into each target's fill function.
using Words = uint32_t __attribute__((vector_size(4 * kPacketSamples)));
using Ints = int32_t __attribute__((vector_size(4 * kPacketSamples)));
using Floats = float __attribute__((vector_size(4 * kPacketSamples)));

// reverse_bits of every lane: swap halves, bytes, nibbles, bit pairs, bits (baseline x86-64
// has no byte shuffle for a vector bswap).
[[gnu::always_inline]] inline Words reverse_lane_bits(Words x) {
  x = (x >> 16) | (x << 16);
  x = ((x >> 8) & 0x00FF00FFu) | ((x & 0x00FF00FFu) << 8);
  x = ((x >> 4) & 0x0F0F0F0Fu) | ((x & 0x0F0F0F0Fu) << 4);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  return ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
}

// fixed_point_to_unit_float of every lane (the top 24 bits convert to float exactly).
[[gnu::always_inline]] inline Floats lane_unit_floats(Words x) {
  return __builtin_convertvector(__builtin_convertvector(x >> 8, Ints), Floats) * 0x1p-24f;
}

using PairPoints = float[kPacketPairs][kPacketSamples];

// owen_sobol_2d_reversed_index, one lane per sample.
[[gnu::always_inline]] inline void fill_lanes(const PairSeeds* seeds, uint32_t first_sample, PairPoints& x_out,
                                              PairPoints& y_out) {
  Words index;
  for (int lane = 0; lane < kPacketSamples; ++lane) index[lane] = first_sample + static_cast<uint32_t>(lane);
  const Words reversed_index = reverse_lane_bits(index);
  for (uint32_t pair = 0; pair < kPacketPairs; ++pair) {
    const PairSeeds& s = seeds[pair];
    const Words shuffled = reverse_lane_bits(laine_karras_permutation(reversed_index, s.shuffle));
    const Floats x = lane_unit_floats(reverse_lane_bits(laine_karras_permutation(shuffled, s.x)));
    const Floats y =
        lane_unit_floats(reverse_lane_bits(laine_karras_permutation(sobol_dimension1_reversed(shuffled), s.y)));
    std::memcpy(x_out[pair], &x, sizeof x);
    std::memcpy(y_out[pair], &y, sizeof y);
  }
}

void fill_baseline(const PairSeeds* seeds, uint32_t first, PairPoints& x, PairPoints& y) {
  fill_lanes(seeds, first, x, y);
}

#if defined(__x86_64__) || defined(__i386__)
__attribute__((target("avx2"))) void fill_avx2(const PairSeeds* seeds, uint32_t first, PairPoints& x, PairPoints& y) {
  fill_lanes(seeds, first, x, y);
}
__attribute__((target("avx512f"))) void fill_avx512(const PairSeeds* seeds, uint32_t first, PairPoints& x,
                                                    PairPoints& y) {
  fill_lanes(seeds, first, x, y);
}
#endif

using FillFunction = void (*)(const PairSeeds*, uint32_t, PairPoints&, PairPoints&);

FillFunction fill_function(LaneIsa isa) {
  switch (isa) {
#if defined(__x86_64__) || defined(__i386__)
    case LaneIsa::Avx512:
      return fill_avx512;
    case LaneIsa::Avx2:
      return fill_avx2;
#endif
    case LaneIsa::Baseline:
      return fill_baseline;
    default:
      throw std::logic_error("SamplePacket: instruction set not compiled in");
  }
}

// Chosen once: the CPU does not change while the library is loaded.
const FillFunction widest_fill = fill_function(supported_lane_isas().back());

// Gathers the packet's pair seeds (the fill functions take plain arrays) and fills with `fill`.
void fill_packet(FillFunction fill, const PixelSeeds& seeds, uint32_t first_sample, PairPoints& x, PairPoints& y) {
  PairSeeds pair_seeds[kPacketPairs];
  for (uint32_t pair = 0; pair < kPacketPairs; ++pair) pair_seeds[pair] = seeds.pair(pair);
  fill(pair_seeds, first_sample, x, y);
}

}  // namespace

std::vector<LaneIsa> supported_lane_isas() {
  std::vector<LaneIsa> isas{LaneIsa::Baseline};
#if defined(__x86_64__) || defined(__i386__)
  __builtin_cpu_init();  // may run before libgcc's own initialisation (static constructors)
  if (__builtin_cpu_supports("avx2")) isas.push_back(LaneIsa::Avx2);
  if (__builtin_cpu_supports("avx512f")) isas.push_back(LaneIsa::Avx512);
#endif
  return isas;
}

SamplePacket::SamplePacket(const PixelSeeds& seeds, uint32_t first_sample)
    : seeds_(seeds), first_sample_(first_sample) {
  fill_packet(widest_fill, seeds, first_sample, x_, y_);
}

SamplePacket::SamplePacket(const PixelSeeds& seeds, uint32_t first_sample, LaneIsa isa)
    : seeds_(seeds), first_sample_(first_sample) {
  const std::vector<LaneIsa> supported = supported_lane_isas();
  if (std::find(supported.begin(), supported.end(), isa) == supported.end())
    throw std::invalid_argument("SamplePacket: this CPU lacks the requested instruction set");
  fill_packet(fill_function(isa), seeds, first_sample, x_, y_);
}

}  // namespace matrender
