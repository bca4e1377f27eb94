#include "matrender/frame.h"

#include <cstddef>

namespace matrender {
namespace {

constexpr int channels_of(const matgeom::MaterialParameterInfo& info) {
  return info.kind == matgeom::ParameterKind::Color ? 3 : 1;
}

}  // namespace

const std::vector<AovName>& aov_names() {
  static const std::vector<AovName> names = [] {
    std::vector<AovName> list;
    for (const matgeom::MaterialParameterInfo& info : matgeom::kMaterialParameters)
      list.push_back({info.name, parameter_aov(info.id)});
    list.insert(list.end(), {{"normal_world", AovNormalWorld},
                             {"normal_camera", AovNormalCamera},
                             {"depth", AovDepth},
                             {"label", AovLabel},
                             {"part_id", AovPartId},
                             {"alpha", AovAlpha}});
    return list;
  }();
  return names;
}

std::optional<uint32_t> aov_named(std::string_view name) {
  for (const AovName& aov : aov_names())
    if (aov.name == name) return aov.bit;
  return std::nullopt;
}

void FrameBuffers::resize(int w, int h, uint32_t aov_mask) {
  width = w;
  height = h;
  aovs = aov_mask;
  const std::size_t n = static_cast<size_t>(w) * static_cast<size_t>(h);
  auto fit = [&](auto& buffer, uint32_t aov, std::size_t channels, auto fill) {
    buffer.assign((aov_mask & aov) ? n * channels : 0, fill);
  };
  color.assign(n * 3, 0.0f);
  fit(alpha, AovAlpha, 1, 0.0f);
  for (const matgeom::MaterialParameterInfo& info : matgeom::kMaterialParameters)
    fit(parameter(info.id), parameter_aov(info.id), static_cast<size_t>(channels_of(info)), 0.0f);
  fit(normal_world, AovNormalWorld, 3, 0.0f);
  fit(normal_camera, AovNormalCamera, 3, 0.0f);
  fit(depth, AovDepth, 1, 0.0f);
  fit(label, AovLabel, 1, int32_t{0});
  fit(part_id, AovPartId, 1, int32_t{-1});
}

}  // namespace matrender
