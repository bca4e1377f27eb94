#pragma once
// The sun with an angular diameter a > 0, Cycles 3.4's soft distant lamp (scene/light.cpp and
// kernel/light/light.h, LIGHT_DISTANT): a disk of radius r = tan(a / 2) seen at distance 1, of
// irradiance E = S c. Directions are drawn uniformly over that disk, so the solid-angle pdf is
// 1 / (pi r^2 cos^3 t) at angle t off the axis, and the radiance is E times the same, which makes
// every light sample carry exactly E. Rays that leave the scene inside the cone see it, weighed
// against light sampling by MIS; camera rays do not (lamps are invisible to them). A sun whose
// disk is too small for a float (angle 0) is one direction instead (distant_light.h).
#include <optional>
#include <utility>

#include <glm/glm.hpp>

#include "lights/distant_light.h"
#include "lights/lamp_preparation.h"
#include "lights/light_sample.h"
#include "lights/light_type.h"
#include "matrender/lamp.h"

namespace matrender {

class SunLight {
 public:
  explicit SunLight(const SunLamp& light);
  // Whether the sun's disk of directions has a radius a float holds; else it is a distant light.
  static bool has_disk(const SunLamp& light);

  // What rays that leave the scene may see.
  static constexpr LightType type() { return LightType::Infinite; }
  static constexpr bool visible_to_camera() { return false; }
  static constexpr bool same_radiance_everywhere() { return false; }

  std::optional<LightSample> sample(const glm::vec3& p, const ReceivingDirections& receiving, glm::vec2 u) const;
  float pdf(const glm::vec3& direction) const;
  // Light selection's weight: E times the receiving plane's largest cosine into the sun's cone.
  float importance(const glm::vec3& p, const ReceivingDirections& receiving) const;
  glm::vec3 radiance(const glm::vec3& direction) const;

 private:
  // 1 / (pi r^2 cos^3 t) inside the cone, 0 outside; the cone test compares tan t with r, from
  // the cross product, which stays exact for suns far smaller than float's cosines resolve.
  float density(const glm::vec3& direction) const;

  glm::vec3 to_sun_;
  glm::vec3 irradiance_;
  float disk_radius_ = 0.0f;  // tan(angle / 2)
  float inverse_disk_area_ = 0.0f;
  float cos_half_angle_ = 1.0f, sin_half_angle_ = 0.0f;
  float mean_irradiance_ = 0.0f;
};

// A sun renders as a distant light of one direction at angle 0, else as a sun light.
template <>
struct LampPreparation<SunLamp> {
  static void check(const SunLamp& sun);
  template <class Add>
  static void prepare(const SunLamp& light, Add&& add) {
    if (SunLight::has_disk(light))
      std::forward<Add>(add)(SunLight(light));
    else
      std::forward<Add>(add)(DistantLight(light));
  }
};

}  // namespace matrender
