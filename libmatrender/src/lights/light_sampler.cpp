#include "lights/light_sampler.h"

#include <algorithm>
#include <type_traits>
#include <variant>

#include "sampling/warp.h"
#include "scene/scene_data.h"

namespace matrender {
namespace {

// The lights of one type among `prepared`, in scene order.
std::vector<Light> of_type(const std::vector<Light>& prepared, LightType type) {
  std::vector<Light> lights;
  for (const Light& light : prepared)
    if (light_type(light) == type) lights.push_back(light);
  return lights;
}

}  // namespace

LightSampler LightSampler::for_scene(const SceneData& scene, LightSelection selection) {
  std::vector<MeshEmitter> emitters;
  for (uint32_t mesh = 0; mesh < scene.meshes.size(); ++mesh)
    if (!scene.meshes[mesh].enabled) continue;
    else if (std::optional<MeshEmitter> emitter = MeshEmitter::of_mesh(scene, mesh))
      emitters.push_back(std::move(*emitter));
  return LightSampler(scene.lamps, scene.world, selection, emitters);
}

LightSampler::LightSampler(const std::vector<Lamp>& lights, const WorldLight& world, LightSelection selection,
                           const std::vector<MeshEmitter>& emitters)
    : selection_(selection) {
  std::vector<Light> prepared;
  // Each described light as the implementation it renders with (its LampPreparation's prepare).
  for (const Lamp& light : lights)
    std::visit(
        [&](const auto& described) {
          using Description = std::decay_t<decltype(described)>;
          LampPreparation<Description>::prepare(described,
                                          [&](auto implementation) { prepared.emplace_back(implementation); });
        },
        light);
  // Area lamps first, rectangles before the others: the lamp-hit query and light selection
  // treat the rectangles together, and rays find the others (is_shaped_lamp) by their own
  // intersect().
  std::vector<RectLight> rects;
  for (const Light& light : prepared)
    if (const auto* rect = std::get_if<RectLight>(&light)) rects.push_back(*rect);
  rects_ = RectLights(rects);
  lights_.assign(rects.begin(), rects.end());
  rect_count_ = rects.size();
  for (const RectLight& rect : rects) camera_visible_lamps_ = camera_visible_lamps_ || rect.visible_to_camera();
  for (const Light& light : of_type(prepared, LightType::Area))
    if (!std::holds_alternative<RectLight>(light)) lights_.push_back(light);
  shaped_lamp_count_ = lights_.size() - rect_count_;
  // Then the meshes' emitting triangles, which rays find by hitting the mesh.
  for (const MeshEmitter& emitter : emitters) {
    if (emitter.mesh() >= emitter_of_mesh_.size()) emitter_of_mesh_.resize(emitter.mesh() + 1, -1);
    emitter_of_mesh_[emitter.mesh()] = static_cast<int32_t>(lights_.size());
    lights_.emplace_back(emitter);
  }
  // Then the lights only light sampling reaches, and those rays that leave the scene see.
  for (const LightType type : {LightType::DeltaPosition, LightType::DeltaDirection, LightType::Infinite})
    for (const Light& light : of_type(prepared, type)) lights_.push_back(light);
  if (const auto* map = std::get_if<EnvironmentLight>(&world); map && !map->black()) lights_.emplace_back(*map);
  sampled_count_ = lights_.size();
  // A uniform background is no light to sample (uniform_background.h), only one to see.
  if (const auto* uniform = std::get_if<UniformBackground>(&world);
      uniform && uniform->radiance(glm::vec3(0.0f, 0.0f, 1.0f)) != glm::vec3(0.0f))
    lights_.emplace_back(*uniform);
  for (size_t i = 0; i < lights_.size(); ++i)
    if (light_type(lights_[i]) == LightType::Infinite) infinite_.push_back(i);
}

PickSite LightSampler::site(const glm::vec3& p, const ReceivingDirections& receiving) const {
  PickSite site;
  site.p = p;
  site.receiving = receiving;
  if (selection_ != LightSelection::Importance) return site;
  if (sampled_count_ <= PickSite::kKeptWeights) {
    // The rectangles all at once, then the other lights one by one.
    rects_.importance(p, receiving, site.weights.data());
    for (size_t i = rect_count_; i < sampled_count_; ++i)
      site.weights[i] = with_light(lights_[i], [&](const auto& light) { return light.importance(p, receiving); });
    for (size_t i = 0; i < sampled_count_; ++i) site.total_importance += site.weights[i];
    return site;
  }
  for (size_t i = 0; i < sampled_count_; ++i) site.total_importance += importance(i, site);
  return site;
}

float LightSampler::importance(size_t index, const PickSite& site) const {
  if (sampled_count_ <= PickSite::kKeptWeights) return site.weights[index];
  return with_light(lights_[index], [&](const auto& light) { return light.importance(site.p, site.receiving); });
}

float LightSampler::pick_probability(size_t index, const PickSite& site) const {
  if (selection_ == LightSelection::Uniform) return empty() ? 0.0f : 1.0f / static_cast<float>(sampled_count_);
  return site.total_importance > 0.0f ? importance(index, site) / site.total_importance : 0.0f;
}

std::optional<LightSampler::Pick> LightSampler::pick(const PickSite& site, float* u) const {
  if (empty()) return std::nullopt;
  if (selection_ == LightSelection::Uniform) {
    const float scaled = *u * static_cast<float>(sampled_count_);
    const size_t index = std::min(static_cast<size_t>(scaled), sampled_count_ - 1);
    *u = std::min(scaled - static_cast<float>(index), 0x1.fffffep-1f);
    return Pick{index, 1.0f / static_cast<float>(sampled_count_)};
  }
  if (!(site.total_importance > 0.0f)) return std::nullopt;
  // Walk the lights' intervals of the total until u's falls in one. The kept weights are read
  // in a loop of their own: through importance() the walk tested for them at every light.
  const auto walk = [&](const auto& weight_of) -> std::optional<Pick> {
    const float target = *u * site.total_importance;
    float below = 0.0f;
    size_t last_lit = sampled_count_;
    for (size_t i = 0; i < sampled_count_; ++i) {
      const float weight = weight_of(i);
      if (!(weight > 0.0f)) continue;
      last_lit = i;
      if (target < below + weight || i + 1 == sampled_count_) {
        *u = std::clamp((target - below) / weight, 0.0f, 0x1.fffffep-1f);
        return Pick{i, weight / site.total_importance};
      }
      below += weight;
    }
    // Rounding left u past the last interval: it belongs to the last light that has one.
    if (last_lit == sampled_count_) return std::nullopt;
    *u = 0x1.fffffep-1f;
    return Pick{last_lit, weight_of(last_lit) / site.total_importance};
  };
  if (sampled_count_ <= PickSite::kKeptWeights) return walk([&](size_t i) { return site.weights[i]; });
  return walk([&](size_t i) { return importance(i, site); });
}

std::optional<LightSample> LightSampler::sample(const PickSite& site, glm::vec2 u) const {
  const std::optional<Pick> picked = pick(site, &u.x);
  if (!picked) return std::nullopt;
  std::optional<LightSample> s = with_light(lights_[picked->index], [&](const auto& light) {
    std::optional<LightSample> drawn = light.sample(site.p, site.receiving, u);
    // Only light sampling reaches a delta light: the integrator weighs its samples by no MIS.
    if (drawn) drawn->delta = is_delta(std::decay_t<decltype(light)>::type());
    return drawn;
  });
  if (s) s->pdf *= picked->probability;
  return s;
}

glm::vec3 LightSampler::escaped_radiance(const glm::vec3& dir, const ScatteredRay& ray) const {
  glm::vec3 sum(0.0f);
  for (size_t index : infinite_) {
    with_light(lights_[index], [&](const auto& light) {
      if constexpr (std::decay_t<decltype(light)>::type() == LightType::Infinite) {
        if (ray.camera_ray && !light.visible_to_camera()) return;
        sum += found_light_weight(index, ray, [&] { return light.pdf(dir); }) * light.radiance(dir);
      }
    });
  }
  return sum;
}

std::optional<glm::vec3> LightSampler::uniform_camera_background() const {
  for (size_t index : infinite_) {
    const bool varies = with_light(lights_[index], [](const auto& light) {
      if constexpr (std::decay_t<decltype(light)>::type() == LightType::Infinite)
        return light.visible_to_camera() && !light.same_radiance_everywhere();
      return false;
    });
    if (varies) return std::nullopt;
  }
  return escaped_radiance(glm::vec3(0.0f, 0.0f, 1.0f), ScatteredRay());
}

}  // namespace matrender
