#include "matrender/frame.h"

#include <cstddef>
#include <type_traits>

#include <fmt/format.h>

namespace matrender {
namespace {

constexpr int channels_of(const matmaterial::MaterialParameterInfo& info) {
  return info.kind == matmaterial::ParameterKind::Color ? 3 : 1;
}

constexpr uint32_t kAlways = 0;  // the AOV bit of the colour, which every frame has

// Every buffer of a frame with its AOV bit, channels per pixel and fill value: the one list that
// resize() and bytes_for() follow.
template <class Visit>
void visit_buffers(FrameBuffers& frame, Visit&& visit) {
  visit(frame.color, kAlways, 3, 0.0f);
  visit(frame.alpha, AovAlpha, 1, 0.0f);
  for (const matmaterial::MaterialParameterInfo& info : matmaterial::kMaterialParameters)
    visit(frame.parameter(info.id), parameter_aov(info.id), static_cast<std::size_t>(channels_of(info)), 0.0f);
  visit(frame.normal_world, AovNormalWorld, 3, 0.0f);
  visit(frame.normal_camera, AovNormalCamera, 3, 0.0f);
  visit(frame.normal_tangent, AovNormalTangent, 3, 0.0f);
  visit(frame.ambient_occlusion, AovAmbientOcclusion, 1, 0.0f);
  visit(frame.depth, AovDepth, 1, 0.0f);
  visit(frame.label, AovLabel, 1, int32_t{0});
  visit(frame.part_id, AovPartId, 1, int32_t{-1});
  visit(frame.object_id, AovObjectId, 1, int32_t{-1});
  visit(frame.sample_count, AovSampleCount, 1, int32_t{0});
  visit(frame.color_variance, AovColorVariance, 1, 0.0f);
}

}  // namespace

namespace {

// A parameter's AOV: the table's line, and how its values read.
std::string parameter_aov_description(const matmaterial::MaterialParameterInfo& info) {
  const std::string values = info.kind == matmaterial::ParameterKind::Color
                                 ? "linear RGB"
                                 : fmt::format("from {:g} to {:g}", info.min, info.max);
  return fmt::format("the material's {} ({}): {}, at the first hit, the mean over the samples that hit; 0 where none did",
                     info.name, info.description, values);
}

}  // namespace

const std::vector<AovName>& aov_names() {
  static const std::vector<AovName> names = [] {
    std::vector<AovName> list;
    for (const matmaterial::MaterialParameterInfo& info : matmaterial::kMaterialParameters)
      list.push_back({info.name, parameter_aov(info.id), parameter_aov_description(info)});
    list.insert(list.end(),
                {{"normal_world", AovNormalWorld,
                  "the shading normal at the first hit in the world frame (Z up), unit length, the mean over the "
                  "samples that hit renormalised; 0 where none did"},
                 {"normal_camera", AovNormalCamera,
                  "normal_world in the camera's frame: +X image right, +Y image up, +Z toward the viewer"},
                 {"normal_tangent", AovNormalTangent,
                  "what the normal map says at the hit, in its tangent frame (2 texel - 1, +Z along the surface "
                  "normal); (0, 0, 1) without a normal map"},
                 {"ambient_occlusion", AovAmbientOcclusion,
                  "the fraction of cosine-distributed directions around the normal that meet no surface within the "
                  "AO distance (Cycles' AO node), from 0 to 1"},
                 {"depth", AovDepth,
                  "metres along the camera's axis to the hit of the sample nearest the pixel centre; 0 where "
                  "nothing was hit"},
                 {"label", AovLabel, "the material label id of the hit nearest the pixel centre; 0 for the background"},
                 {"part_id", AovPartId, "the object part's id at the hit nearest the pixel centre; -1 for the background"},
                 {"object_id", AovObjectId,
                  "the scene object of the hit nearest the pixel centre, numbered as the scene lists its objects "
                  "from 0; -1 for the background"},
                 {"alpha", AovAlpha, "coverage: the fraction of the pixel's camera samples that hit a surface"},
                 {"sample_count", AovSampleCount,
                  "the camera samples the pixel took: the samples per pixel, fewer where adaptive sampling stopped "
                  "early"},
                 {"color_variance", AovColorVariance,
                  "the variance of the pixel's colour estimate (the mean of its samples' Rec.709 luminance)"}});
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
  visit_buffers(*this, [&](auto& buffer, uint32_t aov, std::size_t channels, auto fill) {
    buffer.assign(aov == kAlways || (aov_mask & aov) ? n * channels : 0, fill);
  });
}

FrameBufferView frame_buffer(FrameBuffers& frame, uint32_t aov_bit) {
  FrameBufferView view;
  visit_buffers(frame, [&](auto& buffer, uint32_t aov, std::size_t channels, auto fill) {
    if (aov != aov_bit) return;
    if constexpr (std::is_same_v<decltype(fill), float>) view.floats = &buffer;
    else view.ints = &buffer;
    view.channels = static_cast<int>(channels);
  });
  return view;
}

double FrameBuffers::bytes_for(int w, int h, uint32_t aov_mask) {
  FrameBuffers unused;
  double bytes_per_pixel = 0.0;
  visit_buffers(unused, [&](auto& buffer, uint32_t aov, std::size_t channels, auto) {
    if (aov == kAlways || (aov_mask & aov)) bytes_per_pixel += static_cast<double>(channels * sizeof(buffer[0]));
  });
  return bytes_per_pixel * static_cast<double>(w) * static_cast<double>(h);
}

}  // namespace matrender
