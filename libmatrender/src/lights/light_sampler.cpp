#include "lights/light_sampler.h"

#include <algorithm>
#include <type_traits>
#include <variant>

namespace matrender {

namespace {

std::vector<PreparedRectLight> prepare_rect_lights(const std::vector<Light>& lights) {
  std::vector<PreparedRectLight> rects;
  for (const Light& light : lights)
    if (const auto* rect = std::get_if<RectLight>(&light)) rects.emplace_back(*rect);
  return rects;
}

}  // namespace

LightSampler::LightSampler(const std::vector<Light>& lights)
    : rects_(prepare_rect_lights(lights)), rect_hits_(rects_) {
  for (const Light& light : lights) {
    std::visit(
        [this](const auto& l) {
          using T = std::decay_t<decltype(l)>;
          if constexpr (!std::is_same_v<T, RectLight>) deltas_.emplace_back(l);
        },
        light);
  }
}

std::optional<LightSample> LightSampler::sample(const glm::vec3& p, const ReceivingDirections& receiving,
                                                glm::vec2 u) const {
  if (empty()) return std::nullopt;
  const float scaled = u.x * static_cast<float>(count());
  const size_t index = std::min(static_cast<size_t>(scaled), count() - 1);
  u.x = std::min(scaled - static_cast<float>(index), 0x1.fffffep-1f);
  std::optional<LightSample> s = index < rects_.size() ? rects_[index].sample(p, receiving, u)
                                                       : deltas_[index - rects_.size()].sample(p);
  if (s) s->pdf *= selection_pdf();
  return s;
}

}  // namespace matrender
