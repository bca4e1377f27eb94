#include "film/film.h"

#include <algorithm>

namespace matrender {

void OcclusionFigures::add(const OcclusionFigures& other) {
  squared_error += other.squared_error;
  max_error = std::max(max_error, other.max_error);
  pixels += other.pixels;
}

Film::Film(FrameBuffers& frame, int width, int height, uint32_t aovs, bool transparent_background,
           const glm::mat3& world_to_camera)
    : frame_(frame),
      world_to_camera_(world_to_camera),
      records_surfaces_((aovs & ~static_cast<uint32_t>(AovAlpha | AovSampleCount | AovColorVariance)) != 0),
      records_variance_((aovs & AovColorVariance) != 0) {
  frame_.resize(width, height, aovs);
  frame_.transparent_background = transparent_background;
  for (const matmaterial::MaterialParameterInfo& info : matmaterial::kMaterialParameters)
    if (aovs & parameter_aov(info.id)) parameter_aovs_.push_back(&info);
}

void Film::resolve(size_t i, const PixelSums& sums, OcclusionFigures& figures) {
  FrameBuffers& frame = frame_;
  if (!frame.sample_count.empty()) frame.sample_count[i] = static_cast<int32_t>(sums.samples);
  if (sums.samples == 0) return;  // cancelled before it began
  const double inv_samples = 1.0 / static_cast<double>(sums.samples);
  const glm::dvec3 color = sums.color * inv_samples;
  for (int c = 0; c < 3; ++c) frame.color[3 * i + c] = static_cast<float>(color[c]);
  if (!frame.alpha.empty()) frame.alpha[i] = static_cast<float>(sums.coverage * inv_samples);
  if (!frame.color_variance.empty() && sums.samples > 1) {
    // The unbiased sample variance over n, the variance of the mean.
    const double mean = matbase::rec709_luminance(color);
    const double spread = std::max(0.0, sums.luminance_squares * inv_samples - mean * mean);
    frame.color_variance[i] = static_cast<float>(spread / (static_cast<double>(sums.samples) - 1.0));
  }
  if (sums.hits == 0) return;
  const float inv_hits = 1.0f / static_cast<float>(sums.hits);
  const float normal_len = glm::length(sums.normal);
  const glm::vec3 normal = normal_len > 0.0f ? sums.normal / normal_len : glm::vec3(0.0f);
  const glm::vec3 normal_camera = world_to_camera_ * normal;
  for (const matmaterial::MaterialParameterInfo* info : parameter_aovs_) {
    std::vector<float>& buffer = frame.parameter(info->id);
    const int channels = info->kind == matmaterial::ParameterKind::Color ? 3 : 1;
    for (int c = 0; c < channels; ++c) buffer[channels * i + c] *= inv_hits;
  }
  if (!frame.normal_tangent.empty()) {
    const glm::vec3 sum(frame.normal_tangent[3 * i], frame.normal_tangent[3 * i + 1], frame.normal_tangent[3 * i + 2]);
    const float tangent_len = glm::length(sum);
    const glm::vec3 tangent_space_normal = tangent_len > 0.0f ? sum / tangent_len : glm::vec3(0.0f, 0.0f, 1.0f);
    for (int c = 0; c < 3; ++c) frame.normal_tangent[3 * i + c] = tangent_space_normal[c];
  }
  for (int c = 0; c < 3; ++c) {
    if (!frame.normal_world.empty()) frame.normal_world[3 * i + c] = normal[c];
    if (!frame.normal_camera.empty()) frame.normal_camera[3 * i + c] = normal_camera[c];
  }
  if (!frame.ambient_occlusion.empty()) {
    frame.ambient_occlusion[i] =
        sums.occlusion.trials > 0 ? static_cast<float>(static_cast<double>(sums.occlusion.escaped) / sums.occlusion.trials)
                                  : 0.0f;
    const double error = sums.occlusion.standard_error();
    figures.squared_error += error * error;
    figures.max_error = std::max(figures.max_error, error);
    ++figures.pixels;
  }
  if (!frame.depth.empty()) frame.depth[i] = sums.depth;
  if (!frame.label.empty()) frame.label[i] = sums.label;
  if (!frame.part_id.empty()) frame.part_id[i] = sums.part;
  if (!frame.object_id.empty()) frame.object_id[i] = sums.object;
}

}  // namespace matrender
