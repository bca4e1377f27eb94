#pragma once
// The scene's rectangle lights together, in the two queries that go over all of them at once:
// the ray test every BSDF-sampled ray makes against every rectangle (for_each_hit: their geometry
// stored as structure-of-arrays in blocks of kBlock, each block tested with SIMD instructions and
// no branch per lamp), and light selection's weight of every rectangle at one shading point
// (importance, light_importance.h: one pass over arrays of their bounds, which compiles to vector
// instructions, four lamps to an SSE instruction). Evaluated one lamp at a time the weights were
// the largest cost of a path vertex after Embree's traversal: at the paper's eight lamps, about
// 1,200 of the 5,600 instructions a sample of render_bench's sphere (callgrind).
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>
#if defined(__SSE__)
#include <xmmintrin.h>
#endif

#include "lights/light_sample.h"
#include "lights/rect_light.h"

namespace matrender {

class RectLights {
 public:
  // One SSE register of lamps: the paper's rig of nine lamps pads to 12, not 16.
  static constexpr size_t kBlock = 4;

  RectLights() = default;
  explicit RectLights(const std::vector<RectLight>& lamps);

  bool empty() const { return power_.empty(); }
  size_t size() const { return power_.size(); }

  // weights[i] = lamps[i].importance(p, receiving) for every lamp (weights holds size()).
  void importance(const glm::vec3& p, const ReceivingDirections& receiving, float* weights) const;

  // Calls visit(lamp_index, t) for every lamp whose emitting side the ray meets at a distance
  // t in (0, t_max), in lamp order.
  template <class Visit>
  void for_each_hit(const glm::vec3& origin, const glm::vec3& dir, float t_max, Visit&& visit) const {
    const Float4 ox = broadcast(origin.x), oy = broadcast(origin.y), oz = broadcast(origin.z);
    const Float4 dx = broadcast(dir.x), dy = broadcast(dir.y), dz = broadcast(dir.z);
    const Float4 t_end = broadcast(t_max);
    const float dir_length2 = glm::dot(dir, dir);
    const Float4 d2 = broadcast(dir_length2);
    for (size_t b = 0; b < blocks_.size(); ++b) {
      const Block& k = blocks_[b];
      const Float4 to_center_x = k.center_x - ox, to_center_y = k.center_y - oy, to_center_z = k.center_z - oz;
      // Cull by each lamp's bounding sphere: skip the block when the ray's line passes every
      // centre farther than the radius, |oc|^2 |d|^2 - (oc.d)^2 > r^2 |d|^2. The relative slack
      // covers the cancellation of that difference for lines through a centre.
      const Float4 along = to_center_x * dx + to_center_y * dy + to_center_z * dz;
      const Float4 oc2 = to_center_x * to_center_x + to_center_y * to_center_y + to_center_z * to_center_z;
      const Int4 near_line = oc2 * d2 - along * along <= (k.radius2 + 1e-5f * oc2) * d2;
      if (lane_mask(near_line) == 0) continue;
      // Plane through the centre with normal z (the lamp's back); it emits toward -z, so a ray
      // sees the emitting side when it travels along +z.
      const Float4 facing = dx * k.z_x + dy * k.z_y + dz * k.z_z;
      const Float4 t = (to_center_x * k.z_x + to_center_y * k.z_y + to_center_z * k.z_z) / facing;
      const Float4 px = t * dx - to_center_x, py = t * dy - to_center_y, pz = t * dz - to_center_z;
      const Float4 lx = px * k.x_x + py * k.x_y + pz * k.x_z;
      const Float4 ly = px * k.y_x + py * k.y_y + pz * k.y_z;
      const Int4 hit = (facing > 0.0f) & (t > 0.0f) & (t < t_end) & (lx <= k.half_x) & (-lx <= k.half_x) &
                       (ly <= k.half_y) & (-ly <= k.half_y);
      // Almost every ray misses every lamp: one branch per block, not one per lamp.
      for (unsigned mask = lane_mask(hit); mask != 0; mask &= mask - 1) {
        const size_t i = static_cast<size_t>(__builtin_ctz(mask));
        visit(b * kBlock + i, t[i]);
      }
    }
  }

 private:
  // GCC/Clang vector extensions: element-wise arithmetic and comparisons (all bits set where
  // true) on kBlock lanes, as SSE on x86-64 and NEON on arm64.
  using Float4 = float __attribute__((vector_size(4 * sizeof(float))));
  using Int4 = int __attribute__((vector_size(4 * sizeof(int))));
  static_assert(kBlock == 4, "Float4 holds one block");

  static Float4 broadcast(float v) { return Float4{v, v, v, v}; }
  // Bit i set where lane i of a comparison result is true.
  static unsigned lane_mask(Int4 m) {
#if defined(__SSE__)
    return static_cast<unsigned>(_mm_movemask_ps(reinterpret_cast<__m128>(m)));
#else
    return static_cast<unsigned>((m[0] & 1) | (m[1] & 2) | (m[2] & 4) | (m[3] & 8));
#endif
  }

  // kBlock lamps: centre, the rectangle's unit axes x, y, z, half side lengths and the squared
  // radius of a sphere about the centre enclosing the rectangle. The last block is padded with
  // lamps of negative size and radius, which no ray hits.
  struct Block {
    Float4 center_x, center_y, center_z;
    Float4 x_x, x_y, x_z;
    Float4 y_x, y_y, y_z;
    Float4 z_x, z_y, z_z;
    Float4 half_x, half_y;
    Float4 radius2;
  };
  std::vector<Block> blocks_;

  // For importance(), one array per quantity: the centre, the lamp's +Z (the side that does not
  // emit), the bounding radius and the power, as RectLight::importance reads them.
  std::vector<float> center_x_, center_y_, center_z_;
  std::vector<float> back_x_, back_y_, back_z_;
  std::vector<float> radius_, power_;
};

}  // namespace matrender
