#pragma once
// The runtime lights of a scene, behind one interface, as the lobes of a BSDF are (pbrt-v4's
// Light). A described lamp (matrender/lamp.h) becomes one of these by its LampPreparation's
// prepare (lamp_preparation.h), declared in the light's own file: a point lamp a PointLight, or
// a DiskLight when it has a radius; a sun a DistantLight, or a SunLight when it has an angle; a
// rectangle lamp a RectLight. A mesh's emitting triangles are a MeshEmitter, the world an
// EnvironmentLight or a UniformBackground. Including this header includes every light's file, and
// so every LampPreparation.
//
// Every light:
//   static constexpr LightType type();   what it is (light_type.h), which decides how the
//                                        sampler and the integrator treat it
//   float importance(p, ReceivingDirections) const;   light selection's weight (light_importance.h)
//   std::optional<LightSample> sample(p, ReceivingDirections, glm::vec2 u) const;
// Area lights, which rays hit, also: pdf(p, wi, t), the solid-angle density of sample() giving
// wi, radiance(dir) toward a ray along dir, and visible_to_camera(); lamps rays find by the
// sampler's own query (LightSampler::for_each_area_hit) intersect(origin, dir, t_max), emissive
// meshes, found by the rays' own hits, pdf(p, wi, t, triangle). Infinite lights, which rays that
// leave the scene see: pdf(direction), radiance(direction), visible_to_camera() and
// same_radiance_everywhere() (radiance does not depend on the direction). Delta lights
// (DeltaPosition, DeltaDirection) need nothing more: only light sampling reaches them.
#include <cstddef>
#include <utility>
#include <variant>

#include "lights/disk_light.h"
#include "lights/distant_light.h"
#include "lights/environment_light.h"
#include "lights/light_type.h"
#include "lights/mesh_emitter.h"
#include "lights/point_light.h"
#include "lights/rect_light.h"
#include "lights/spot_light.h"
#include "lights/sun_light.h"
#include "lights/uniform_background.h"

namespace matrender {

using Light = std::variant<RectLight, DiskLight, MeshEmitter, PointLight,
                                SpotLight, DistantLight, SunLight, UniformBackground,
                                EnvironmentLight>;

// f(the light as its own type). A switch, not std::visit, so that the lights' methods inline
// (GCC calls std::visit's alternatives through a table); the variant above and its cases here
// change together.
template <class F>
decltype(auto) with_light(const Light& light, F&& f) {
  static_assert(std::variant_size_v<Light> == 9, "a new light needs its case here");
  switch (light.index()) {
    case 0: return f(*std::get_if<0>(&light));
    case 1: return f(*std::get_if<1>(&light));
    case 2: return f(*std::get_if<2>(&light));
    case 3: return f(*std::get_if<3>(&light));
    case 4: return f(*std::get_if<4>(&light));
    case 5: return f(*std::get_if<5>(&light));
    case 6: return f(*std::get_if<6>(&light));
    case 7: return f(*std::get_if<7>(&light));
    default: return f(*std::get_if<8>(&light));
  }
}

inline LightType light_type(const Light& light) {
  return with_light(light, [](const auto& l) { return l.type(); });
}

}  // namespace matrender
