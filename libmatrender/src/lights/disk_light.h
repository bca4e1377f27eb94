#pragma once
// Point and spot lamps with a radius, as Cycles 3.4 renders them (kernel/light/light.h,
// lamp_light_sample and lights_intersect for LIGHT_POINT and LIGHT_SPOT): not a sphere but a disk
// of radius R around the lamp's position, turned to face whichever point looks at it, emitting
// radiance I / (pi R^2) for the point lamp's intensity I = P c / (4 pi), times the spot's cone
// factor toward the lit point. Points of the disk are drawn uniformly by area, so the solid-angle
// pdf is t^2 / (pi R^2 cos) for a point at distance t seen at cosine cos off the disk's normal.
// Rays hit the disk too, and both strategies are weighed by MIS; lamps never block light.
#include <optional>

#include <glm/glm.hpp>

#include "lights/light_sample.h"
#include "lights/light_type.h"
#include "matrender/lamp.h"

namespace matrender {

class DiskLight {
 public:
  explicit DiskLight(const PointLamp& light);
  explicit DiskLight(const SpotLamp& light);

  static constexpr LightType type() { return LightType::Area; }

  // A point drawn uniformly on the disk that faces p. Nothing when the whole disk lies below the
  // plane of a reflecting BSDF's shading normal, or outside a spot's cone.
  std::optional<LightSample> sample(const glm::vec3& p, const ReceivingDirections& receiving, glm::vec2 u) const;
  // Solid-angle pdf of sample() from p producing direction wi, given that the ray along it hits
  // the disk at distance t.
  float pdf(const glm::vec3& p, const glm::vec3& wi, float t) const;
  // Light selection's weight at p (light_importance.h); a spot's cone is left out of the bound.
  float importance(const glm::vec3& p, const ReceivingDirections& receiving) const;
  // What a ray along `dir` that hits the disk receives (the spot's cone factor for -dir).
  glm::vec3 radiance(const glm::vec3& dir) const;
  // Lamps other than rectangles stay invisible to camera rays, Blender's default.
  static constexpr bool visible_to_camera() { return false; }
  // The distance in (0, t_max) at which the ray meets the disk facing its origin, if it does.
  std::optional<float> intersect(const glm::vec3& origin, const glm::vec3& dir, float t_max) const;

 private:
  glm::vec3 center_;
  float radius_;
  glm::vec3 radiance_;  // on the axis of a spot
  float intensity_;     // channel mean of the point lamp's I
  glm::vec3 axis_{0.0f, 0.0f, -1.0f};
  float cos_half_angle_ = -1.0f;
  float blend_ = 0.0f;
  bool is_spot_ = false;
};

}  // namespace matrender
