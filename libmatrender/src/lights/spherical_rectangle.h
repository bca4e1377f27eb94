#pragma once
// Uniform sampling of the solid angle a rectangle subtends: Urena, Fajardo, King 2013,
// "An Area-Preserving Parametrization for Spherical Rectangles", EGSR. Set up in double
// precision because the solid angle is a difference of angles near 2 pi.
#include <glm/glm.hpp>

namespace matrender {

class SphericalRectangle {
 public:
  // Rectangle with corner `corner` and edge vectors ex, ey (orthogonal), seen from `origin`.
  SphericalRectangle(const glm::dvec3& origin, const glm::dvec3& corner, const glm::dvec3& ex,
                     const glm::dvec3& ey);

  double solid_angle() const { return solid_angle_; }
  // Point on the rectangle whose direction from the origin is uniform in the solid angle
  // (section 4, eqs. 7-11 of the paper).
  glm::dvec3 sample(glm::dvec2 u) const;

 private:
  glm::dvec3 origin_, x_, y_, z_;
  double x0_, y0_, x1_, y1_, z0_;
  double b0_, b1_, k_, solid_angle_;
};

}  // namespace matrender
