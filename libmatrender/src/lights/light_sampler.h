#pragma once
// The scene's lights and how next-event estimation chooses one of them per shading point: by
// each light's importance there (light_importance.h: its bounded irradiance, 0 where it cannot
// light the point), or uniformly, as Cycles 3.4 does (it has no light tree). Only noise depends on
// the choice. An environment map is one of the lights; a uniform background is not
// (uniform_background.h).
// Also the two ways a ray finds light without sampling it: the one query for the area lights it
// hits, and the infinite lights it sees when it leaves the scene.
#include <array>
#include <cstddef>
#include <optional>
#include <type_traits>
#include <vector>

#include <glm/glm.hpp>

#include "lights/light_sample.h"
#include "lights/rect_lights.h"
#include "lights/light.h"
#include "lights/world_light.h"
#include "sampling/warp.h"
#include "matrender/lamp.h"
#include "matrender/render_settings.h"

namespace matrender {

// Where a light is picked: the shading point, the directions it receives from, and the sum of
// every light's importance there. A ray that leaves it and finds a light weighs that light's
// pick by the same site (MIS).
struct PickSite {
  // Scenes of up to this many lights keep each light's importance here, so that the pick does
  // not evaluate them again (the paper's rig has 6 to 12 lamps).
  static constexpr size_t kKeptWeights = 16;

  glm::vec3 p{0.0f};
  ReceivingDirections receiving;
  float total_importance = 0.0f;
  std::array<float, kKeptWeights> weights;  // filled when the distribution has at most kKeptWeights
};

// How a ray that finds a light came to be, for MIS against the light sample the vertex that
// scattered it took (Veach 1997, section 9.2): the solid-angle density of the BSDF sample that
// made it, whether that bounce was specular, whether it is still the camera's ray, and the site
// where that vertex picked its light.
struct ScatteredRay {
  float bsdf_pdf = 0.0f;
  bool specular = false;
  bool camera_ray = true;
  const PickSite* from = nullptr;
};

// An area lamp other than a rectangle: rays find it by its own intersect(). Rectangles are
// found together (rect_lights.h), emissive meshes by the rays' hits on the mesh.
template <class Prepared>
constexpr bool is_shaped_lamp() {
  return Prepared::type() == LightType::Area && !std::is_same_v<Prepared, RectLight> &&
         !std::is_same_v<Prepared, MeshEmitter>;
}

class SceneData;

class LightSampler {
 public:
  // Every emitter of `scene` prepared for rendering, here and nowhere else: its lamps, its world
  // and the emitting triangles of each of its meshes, which must outlive the sampler.
  static LightSampler for_scene(const SceneData& scene, LightSelection selection);
  // Lamps and a world alone, without meshes. A uniform black world is no light at all.
  LightSampler(const std::vector<Lamp>& lights, const WorldLight& world,
               LightSelection selection = LightSelection::Importance)
      : LightSampler(lights, world, selection, {}) {}

  // The lights next-event estimation draws from are lights(0 .. sampled_count() - 1), placed by
  // their LightType, each kind in scene order: the area lamps (rectangles, then the disks of
  // point and spot lamps with a radius), emissive meshes, then the delta lights (DeltaPosition:
  // point and spot lamps; DeltaDirection: suns of angle 0), then the infinite ones (suns with an
  // angle, then an environment map). After them, outside the distribution, a uniform background
  // that is not black.
  size_t sampled_count() const { return sampled_count_; }
  bool empty() const { return sampled_count_ == 0; }
  const Light& light(size_t i) const { return lights_[i]; }
  LightSelection selection() const { return selection_; }

  // The site at p, its total importance summed (for importance selection).
  PickSite site(const glm::vec3& p, const ReceivingDirections& receiving) const;
  // The probability that a pick at `site` draws light(index), one of the distribution's lights.
  float pick_probability(size_t index, const PickSite& site) const;

  struct Pick {
    size_t index;       // into light()
    float probability;  // of drawing it
  };
  // The light u picks at `site`, each with its pick_probability. *u is then rescaled to [0, 1)
  // within the light's interval, so it can be reused for the point on the light with its 2-D
  // stratification kept (Cycles 3.4, kernel/light/light.h, light_distribution_sample: "rescale
  // to reuse random number"). Nothing when no light can light the site.
  std::optional<Pick> pick(const PickSite& site, float* u) const;

  // A sample of the light u.x picks, with u.x reused (pick); its pdf includes the probability of
  // the pick. Lights wholly outside the site's receiving directions give no sample.
  std::optional<LightSample> sample(const PickSite& site, glm::vec2 u) const;

  bool has_area_lights() const { return !rects_.empty() || shaped_lamp_count_ > 0; }
  // The index of the light that is a mesh's emitting triangles (a MeshEmitter), or
  // nothing.
  std::optional<size_t> emitter_index(uint32_t mesh) const {
    if (mesh >= emitter_of_mesh_.size() || emitter_of_mesh_[mesh] < 0) return std::nullopt;
    return static_cast<size_t>(emitter_of_mesh_[mesh]);
  }
  // Some area lamp is visible to camera rays (most scenes have none, and their camera rays then
  // look for no lamp).
  bool has_camera_visible_lamps() const { return camera_visible_lamps_; }
  // Calls visit(index, area_light, t) for each area lamp (light(index): a rectangle, or a lamp of
  // another shape, such as the disk of a point lamp with a radius) whose emitting side the ray
  // meets at a distance t in (0, t_max), in order. Emissive meshes are not lamps: rays find them
  // by hitting the mesh.
  template <class Visit>
  void for_each_area_hit(const glm::vec3& origin, const glm::vec3& dir, float t_max, Visit&& visit) const {
    rects_.for_each_hit(origin, dir, t_max, [&](size_t index, float t) {
      visit(index, *std::get_if<RectLight>(&lights_[index]), t);
    });
    for (size_t i = rect_count_; i < rect_count_ + shaped_lamp_count_; ++i)
      with_light(lights_[i], [&](const auto& lamp) {
        if constexpr (is_shaped_lamp<std::decay_t<decltype(lamp)>>())
          if (const std::optional<float> t = lamp.intersect(origin, dir, t_max)) visit(i, lamp, *t);
      });
  }

  // The one MIS weight of every light a ray finds, light(index) (a lamp it meets, an emitting
  // mesh it hits, an infinite light it sees): the power heuristic between the ray's BSDF density
  // and the density of light sampling drawing that light and that direction from the ray's site,
  // the pick's probability times light_pdf() (called only when needed); 1 where no light sample
  // competes (a specular bounce, the camera's ray). A light outside the distribution (a uniform
  // background) has no light-sampling density.
  template <class LightPdf>
  float found_light_weight(size_t index, const ScatteredRay& ray, LightPdf&& light_pdf) const {
    if (ray.specular || ray.camera_ray) return 1.0f;
    return power_heuristic(ray.bsdf_pdf, index < sampled_count_ ? pick_probability(index, *ray.from) * light_pdf() : 0.0f);
  }

  // What a ray leaving the scene along dir sees of the infinite lights, each weighed by
  // found_light_weight. A camera ray sees those visible to the camera, whole.
  glm::vec3 escaped_radiance(const glm::vec3& dir, const ScatteredRay& ray) const;
  // What a camera ray that meets nothing sees (its escaped_radiance) when that is the same in
  // every direction; nothing when an infinite light visible to the camera varies with direction.
  std::optional<glm::vec3> uniform_camera_background() const;

 private:
  LightSampler(const std::vector<Lamp>& lights, const WorldLight& world, LightSelection selection,
               const std::vector<MeshEmitter>& emitters);

  std::vector<Light> lights_;
  size_t sampled_count_ = 0;
  std::vector<size_t> infinite_;  // indices of the infinite lights
  // light(index)'s importance at the site: kept there, or evaluated again.
  float importance(size_t index, const PickSite& site) const;

  RectLights rects_;  // lights(0 .. rect_count_ - 1), together
  size_t rect_count_ = 0;
  size_t shaped_lamp_count_ = 0;  // lights(rect_count_ .. rect_count_ + shaped_lamp_count_ - 1)
  std::vector<int32_t> emitter_of_mesh_;  // index into lights_ by mesh, -1 for none
  bool camera_visible_lamps_ = false;
  LightSelection selection_ = LightSelection::Importance;
};

}  // namespace matrender
