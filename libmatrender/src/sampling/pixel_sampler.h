#pragma once
// The random numbers of one camera sample (owen_sobol.h): the first kPacketPairs pairs come
// from the sample's packet (sample_packet.h), later ones are computed when a path reaches them.
#include <cstdint>

#include <glm/glm.hpp>

#include "sampling/owen_sobol.h"
#include "sampling/sample_packet.h"

namespace matrender {

// Pair k is point `sample` of owen_sobol_2d_reversed_index with the pixel's seeds of pair k.
class PixelSampler {
 public:
  // One sample on its own, every pair computed scalar (the reference the packets are tested
  // against; the renderer uses packets).
  PixelSampler(const PixelSeeds& seeds, uint32_t sample_index)
      : seeds_(seeds), reversed_index_(reverse_bits(sample_index)) {}
  // Lane `lane` of a packet, which must outlive the sampler.
  PixelSampler(const SamplePacket& packet, int lane)
      : seeds_(packet.seeds()),
        reversed_index_(reverse_bits(packet.first_sample() + static_cast<uint32_t>(lane))),
        packet_(&packet),
        lane_(lane) {}

  glm::vec2 get_2d(uint32_t pair) const {
    if (packet_ && pair < kPacketPairs) return packet_->point(pair, lane_);
    return owen_sobol_2d_reversed_index(reversed_index_, seeds_.pair(pair));
  }

 private:
  const PixelSeeds& seeds_;
  uint32_t reversed_index_;
  const SamplePacket* packet_ = nullptr;
  int lane_ = 0;
};

}  // namespace matrender
