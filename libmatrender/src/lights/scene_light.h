#pragma once
// The lights of a scene, prepared for rendering, behind one interface. The set is open: a new
// light is a class with the methods below, added to `SceneLight`.
//
// Every light:
//   static LightType type();   what it is (light_type.h)
//   std::optional<LightSample> sample(p, ReceivingDirections, glm::vec2 u) const;
// Which lights next-event estimation draws from is LightSampler's choice (light_sampler.h).
// Lamps with an area, which rays hit (LightSampler::for_each_area_hit finds them): pdf(p, wi, t), the
// solid-angle density of sample() giving wi, radiance(dir) toward a ray along dir, and
// visible_to_camera(). Emissive meshes (Area too) are found by the rays' own hits: pdf(p, wi, t,
// triangle). Infinite lights, which rays that leave the scene see: pdf(direction),
// radiance(direction), visible_to_camera() and same_radiance_everywhere() (radiance does not
// depend on the direction); those that sample() can draw are in the distribution.
#include <variant>

#include "lights/disk_lamp.h"
#include "lights/environment_light.h"
#include "lights/light_type.h"
#include "lights/mesh_emitter.h"
#include "lights/rect_light.h"
#include "lights/spot_light.h"
#include "lights/sun_light.h"
#include "lights/uniform_background.h"

namespace matrender {

using SceneLight = std::variant<PreparedRectLight, PreparedDiskLamp, PreparedMeshEmitter, PreparedDeltaLight,
                                PreparedSunLight, UniformBackground, PreparedEnvironmentLight>;

// f(the light as its own type). A switch, not std::visit, so that the lights' methods inline
// (GCC calls std::visit's alternatives through a table).
template <class F>
decltype(auto) with_light(const SceneLight& light, F&& f) {
  static_assert(std::variant_size_v<SceneLight> == 7, "a new light needs its case here");
  switch (light.index()) {
    case 0: return f(*std::get_if<0>(&light));
    case 1: return f(*std::get_if<1>(&light));
    case 2: return f(*std::get_if<2>(&light));
    case 3: return f(*std::get_if<3>(&light));
    case 4: return f(*std::get_if<4>(&light));
    case 5: return f(*std::get_if<5>(&light));
    default: return f(*std::get_if<6>(&light));
  }
}

inline LightType light_type(const SceneLight& light) {
  return with_light(light, [](const auto& l) { return l.type(); });
}

}  // namespace matrender
