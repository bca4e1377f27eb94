#pragma once
// The environment light: radiance from every direction, read from an equirectangular image with
// Cycles 3.4's mapping (kernel/geom/..., direction_to_equirectangular with its default range):
//   u = 0.5 - atan2(y, x) / (2 pi),   v = 1 - acos(z) / pi,
// so +X looks at the image's centre column, +Y a quarter to its left, and +Z at its top row.
// Directions are drawn from a 2-D piecewise-constant density over the image's texels
// (pbrt-v4, section 12.5.2), combined with BSDF sampling by MIS.
#include <memory>
#include <optional>

#include <glm/glm.hpp>

#include "lights/light_sample.h"
#include "lights/light_type.h"
#include "matrender/background.h"
#include "sampling/piecewise_constant.h"

namespace matrender {

class EnvironmentLight {
 public:
  // Builds the sampling density: each texel weighs the integral of the bilinear lookup's channel
  // mean over its cell times the sine of its polar angle (the cell's solid angle). Throws
  // std::invalid_argument for a map without an image or with a negative or non-finite strength.
  explicit EnvironmentLight(const EnvironmentMap& map);

  static constexpr LightType type() { return LightType::Infinite; }
  static constexpr bool visible_to_camera() { return true; }
  static constexpr bool same_radiance_everywhere() { return false; }

  // A direction drawn from the density; nothing when the map is black. `receiving` plays no
  // part: most directions of a map are seen from any side.
  std::optional<LightSample> sample(const glm::vec3& p, const ReceivingDirections& receiving, glm::vec2 u) const;
  // Solid-angle density of sample() drawing the world direction d.
  float pdf(const glm::vec3& d) const;
  // Light selection's weight: the irradiance a plane would get from the map's mean radiance, pi
  // times it (the map may light any point from some side).
  float importance(const glm::vec3& /*p*/, const ReceivingDirections& /*receiving*/) const { return importance_; }
  glm::vec3 radiance(const glm::vec3& d) const;
  // The map is black: nothing to sample.
  bool black() const { return !(distribution_->integral() > 0.0); }

 private:
  glm::vec3 to_map(const glm::vec3& d) const;
  glm::vec3 from_map(const glm::vec3& d) const;

  TexturePtr image_;
  float strength_ = 1.0f;
  float cos_rotation_ = 1.0f;
  float sin_rotation_ = 0.0f;
  float importance_ = 0.0f;
  std::shared_ptr<const PiecewiseConstant2D> distribution_;  // over (u, v), shared by copies
};

}  // namespace matrender
