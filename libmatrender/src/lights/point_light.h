#pragma once
// A point lamp of radius 0, Cycles 3.4's conventions (intern/cycles/kernel/light/point.h;
// docs/conventions.md, Lamps): intensity I = P c / (4 pi) W/sr in every direction, reached only by
// light sampling. With a radius it is a disk lamp instead (disk_lamp.h).
#include <cmath>
#include <optional>
#include <utility>

#include <glm/glm.hpp>

#include "lights/disk_lamp.h"
#include "lights/light_checks.h"
#include "lights/light_kind.h"
#include "lights/light_sample.h"
#include "lights/light_type.h"
#include "matbase/pi.h"
#include "matrender/light.h"
#include "scene_description/scene_file_node.h"
#include "util/channel_average.h"

namespace matrender {

class PreparedPointLight {
 public:
  explicit PreparedPointLight(const PointLight& light)
      : position_(light.position),
        intensity_(light.power * light.color / (4.0 * matbase::kPi)),
        mean_intensity_(channel_average(intensity_)) {}

  static constexpr LightType type() { return LightType::DeltaPosition; }

  // Light selection's weight at p: the irradiance I cos / d^2 it gives, exactly (light_importance.h).
  float importance(const glm::vec3& p, const ReceivingDirections& receiving) const {
    const glm::vec3 to_light = position_ - p;
    const float dist2 = glm::dot(to_light, to_light);
    if (!(dist2 > 0.0f)) return 0.0f;
    const glm::vec3 wi = to_light / std::sqrt(dist2);
    const float cosine = receiving.every_direction ? 1.0f : std::max(0.0f, glm::dot(wi, receiving.normal));
    return mean_intensity_ * cosine / dist2;
  }

  // The one direction toward the lamp; `receiving` and u play no part.
  std::optional<LightSample> sample(const glm::vec3& p, const ReceivingDirections& /*receiving*/,
                                    glm::vec2 /*u*/) const {
    const glm::vec3 to_light = position_ - p;
    const float dist2 = glm::dot(to_light, to_light);
    if (!(dist2 > 0.0f)) return std::nullopt;
    const float dist = std::sqrt(dist2);
    LightSample s;
    s.wi = to_light / dist;
    s.distance = dist;
    const float factor = 1.0f / dist2;
    if (!(factor > 0.0f)) return std::nullopt;
    s.radiance = intensity_ * factor;
    s.pdf = 1.0f;
    return s;
  }

 private:
  glm::vec3 position_;
  glm::vec3 intensity_;
  float mean_intensity_;
};

// The scene file's "point" lamp: position, power, color, radius. With a radius it renders as a
// disk lamp.
template <>
struct LightKind<PointLight> {
  static constexpr const char* kSceneFileType = "point";
  static PointLight read(const SceneFileNode& node) {
    node.expect_keys({"type", "position", "power", "color", "radius"});
    PointLight light;
    light.position = read_vec3(node.required("position"));
    light.power = node.required("power").non_negative();
    if (auto color = node.find("color")) light.color = read_color(*color);
    if (auto radius = node.find("radius")) light.radius = radius->non_negative();
    return light;
  }
  static void check(const PointLight& light) {
    check_point_lamp(light.position, light.power, light.color, light.radius);
  }
  template <class Add>
  static void prepare(const PointLight& light, Add&& add) {
    if (light.radius > 0.0)
      std::forward<Add>(add)(PreparedDiskLamp(light));
    else
      std::forward<Add>(add)(PreparedPointLight(light));
  }
};

}  // namespace matrender
