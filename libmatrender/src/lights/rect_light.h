#pragma once
// One-sided rectangular area lamp, Cycles 3.4 conventions: radiance L = P c / (4 a b) emitted
// toward the lamp's local -Z (docs/conventions.md, Lamps). Sampled by solid angle.
#include <array>
#include <optional>
#include <utility>

#include <glm/glm.hpp>

#include "lights/lamp_preparation.h"
#include "lights/light_sample.h"
#include "lights/light_type.h"
#include "lights/spherical_rectangle.h"
#include "matrender/lamp.h"

namespace matrender {

class RectLight {
 public:
  explicit RectLight(const RectLamp& light);

  static constexpr LightType type() { return LightType::Area; }

  // Samples a point uniformly in the solid angle the lamp subtends from p (by area when that
  // solid angle is too small to compute accurately). Returns nothing when p does not see the
  // emitting side, or when the whole lamp lies outside the directions p receives from (on or
  // below the plane of a reflecting BSDF's shading normal): the sample could only cost time.
  std::optional<LightSample> sample(const glm::vec3& p, const ReceivingDirections& receiving, glm::vec2 u) const;
  // Solid-angle pdf of sample() producing direction wi from p, given that the ray hits the lamp
  // at distance t.
  float pdf(const glm::vec3& p, const glm::vec3& wi, float t) const;
  // Light selection's weight at p (light_importance.h): 0 behind the lamp or wholly below the
  // receiving plane.
  float importance(const glm::vec3& p, const ReceivingDirections& receiving) const;
  // The same toward every ray that meets the emitting side.
  glm::vec3 radiance(const glm::vec3& /*dir*/) const { return radiance_; }
  bool visible_to_camera() const { return visible_to_camera_; }
  // The lamp's rectangle; its z is the lamp's +Z, the side that does not emit.
  const Rectangle3& rectangle() const { return rect_; }
  glm::vec3 center() const { return center_; }
  // Half the diagonal: the radius of the sphere about center() that holds the lamp.
  float bounding_radius() const { return bounding_radius_; }
  // Radiance times area, channel mean.
  float power() const { return power_; }

 private:
  bool sees_emitting_side(const glm::vec3& p) const;
  bool below_plane(const glm::vec3& p, const glm::vec3& n) const;

  Rectangle3 rect_;
  glm::vec3 center_{0.0f};
  std::array<glm::vec3, 4> corners_{};
  float area_ = 0.0f;
  float bounding_radius_ = 0.0f;  // half the diagonal
  float power_ = 0.0f;            // channel mean of radiance times area
  glm::vec3 radiance_{0.0f};
  bool visible_to_camera_ = false;
};

// A rectangle lamp renders as a rectangle light.
template <>
struct LampPreparation<RectLamp> {
  static void check(const RectLamp& light);
  template <class Add>
  static void prepare(const RectLamp& light, Add&& add) {
    std::forward<Add>(add)(RectLight(light));
  }
};

}  // namespace matrender
