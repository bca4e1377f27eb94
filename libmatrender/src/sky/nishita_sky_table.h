#pragma once
// Blender 3.4's Nishita sky as Cycles evaluates it (scene/shader_nodes.cpp precomputes, and
// kernel/svm/sky.h reads): the atmosphere (nishita_atmosphere.h) tabulated at 512 x 128
// directions of the upper hemisphere, the sun's azimuth at the table's centre column, rows
// denser towards the horizon (row y at elevation (90 degrees + half a row) (y / 128)^2); and two
// radiances of the sun, at the disc's lowest and highest elevation, between which the disc is
// interpolated and darkened towards its limb.
#include <vector>

#include <glm/glm.hpp>

#include "matrender/sky.h"

namespace matrender {

class NishitaSkyTable {
 public:
  static constexpr int kWidth = 512;
  static constexpr int kHeight = 128;

  explicit NishitaSkyTable(const NishitaSky& sky);

  // Scene-linear Rec.709 radiance of the sky along unit `direction` without the disc (and
  // without the Background's strength): the table read bilinearly with its edges extended, the
  // ground (below the horizon) the horizon's row faded by (1 + 2.5 z)^3 and black below z = -0.4.
  glm::dvec3 sky(const glm::dvec3& direction) const;
  // The disc's radiance along `direction` (intensity included, strength not): 0 outside it and
  // below the horizon.
  glm::dvec3 disc(const glm::dvec3& direction) const;
  // Unit direction towards the sun's centre.
  const glm::dvec3& to_sun() const { return to_sun_; }

 private:
  glm::dvec3 table_xyz(double x, double y) const;

  NishitaSky sky_;
  glm::dvec3 to_sun_;
  std::vector<glm::dvec3> xyz_;  // kWidth x kHeight, row 0 at the horizon
  glm::dvec3 sun_bottom_xyz_{0.0}, sun_top_xyz_{0.0};
};

}  // namespace matrender
