#pragma once
// The random numbers of a packet of consecutive camera samples of one pixel, for the pairs that
// nearly every path uses (the pixel-filter offset, then the first vertex's lamp and BSDF
// choices): owen_sobol_2d_reversed_index for all samples at once, lane-parallel, with the
// widest integer vectors the CPU has. Every instruction set gives the same bits as the scalar
// code: the operations are the same 32-bit integer ones.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "sampling/owen_sobol.h"

namespace matrender {

constexpr int kPacketSamples = 16;
constexpr uint32_t kPacketPairs = 3;

// The instruction sets the packet code is compiled for, narrowest first (Baseline: the
// build's own target, SSE2 on x86-64).
enum class LaneIsa { Baseline, Avx2, Avx512 };

// Those this CPU runs, narrowest first.
std::vector<LaneIsa> supported_lane_isas();

class SamplePacket {
 public:
  // Samples first_sample, first_sample + 1, ... of the pixel whose seeds these are, computed
  // with the widest supported instruction set, or with `isa` (which must be supported).
  SamplePacket(const PixelSeeds& seeds, uint32_t first_sample);
  SamplePacket(const PixelSeeds& seeds, uint32_t first_sample, LaneIsa isa);

  const PixelSeeds& seeds() const { return seeds_; }
  uint32_t first_sample() const { return first_sample_; }
  glm::vec2 point(uint32_t pair, int lane) const { return {x_[pair][lane], y_[pair][lane]}; }

 private:
  const PixelSeeds& seeds_;
  uint32_t first_sample_;
  alignas(64) float x_[kPacketPairs][kPacketSamples];
  alignas(64) float y_[kPacketPairs][kPacketSamples];
};

}  // namespace matrender
