#pragma once
// Uniform sampling of the solid angle a rectangle subtends: Urena, Fajardo, King 2013,
// "An Area-Preserving Parametrization for Spherical Rectangles", EGSR. Single precision, like
// Cycles (kernel/light/area.h); the solid angle is summed from arcsines (below) so that it keeps
// its relative precision for small rectangles instead of being a difference near 2 pi.
#include <glm/glm.hpp>

namespace matrender {

// A rectangle in space: corner, orthonormal edge directions x and y with lengths, z = x cross y.
struct Rectangle3 {
  glm::vec3 corner{0.0f}, x{1.0f, 0.0f, 0.0f}, y{0.0f, 1.0f, 0.0f}, z{0.0f, 0.0f, 1.0f};
  float length_x = 1.0f, length_y = 1.0f;
};

class SphericalRectangle {
 public:
  // The rectangle as seen from `origin` (which must not lie in its plane).
  SphericalRectangle(const glm::vec3& origin, const Rectangle3& rect);

  float solid_angle() const { return solid_angle_; }
  // Point on the rectangle whose direction from the origin is uniform in the solid angle
  // (section 4, eqs. 7-11 of the paper).
  glm::vec3 sample(glm::vec2 u) const;

 private:
  glm::vec3 origin_, x_, y_, z_;
  float x0_, y0_, x1_, y1_, z0_;
  float b0_, b1_, k_, solid_angle_;
  float one_minus_b0_sq_;  // 1 - b0^2 without the cancellation
};

}  // namespace matrender
