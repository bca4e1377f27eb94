#pragma once
// The frame as it accumulates (pbrt-v4's film, section 5.4): every camera sample adds its
// radiance, its coverage and, where it hit, its first surface to its pixel's sums, and resolve()
// turns a pixel's sums into its colour and AOVs (matrender/frame.h says how each is filtered).
// Colour, alpha, the variance, the normals, ambient occlusion and the nearest hit's depth, label
// and part sum in PixelSums; the material parameters and the tangent-space normal, whose width
// depends on the AOVs asked for, sum in the frame's own arrays and are divided in place by
// resolve(). So adaptive sampling, which keeps every pixel's sums between its rounds, keeps a
// small PixelSums per pixel. A pixel is accumulated and resolved by one thread at a time.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include <glm/glm.hpp>

#include "integrator/ambient_occlusion.h"
#include "matbase/image/srgb.h"
#include "matrender/frame.h"
#include "scene/surface_shading.h"
#include "util/finite.h"

namespace matrender {

struct PixelSums {
  glm::dvec3 color{0.0};
  glm::dvec3 second_estimate{0.0};  // adaptive sampling: the colour of the samples of its second half
  double luminance_squares = 0.0;   // summed squared Rec.709 luminance of the samples, for the variance
  glm::dvec3 first_half{0.0};       // rendering to an error: the colour of the first half of the samples
  double first_half_luminance_squares = 0.0;  // and their luminance squares (a half's variance)
  double coverage = 0.0;            // summed 1 - transparency of the camera rays
  OcclusionTally occlusion;
  OcclusionSite last_hit;  // where occlusion rays the pixel still misses at the end start
  glm::vec3 normal{0.0f};
  uint32_t samples = 0;
  int32_t hits = 0;
  float nearest_offset2 = std::numeric_limits<float>::infinity();
  float depth = 0.0f;
  int32_t label = 0;
  int32_t part = -1;
  int32_t object = -1;
};

// What resolve() found of a pixel's ambient occlusion, for the render's statistics.
struct OcclusionFigures {
  double squared_error = 0.0;
  double max_error = 0.0;
  uint64_t pixels = 0;

  void add(const OcclusionFigures& other);
};

class Film {
 public:
  // Sizes `frame` for width x height with `aovs` and accumulates into it.
  Film(FrameBuffers& frame, int width, int height, uint32_t aovs, bool transparent_background,
       const glm::mat3& world_to_camera);

  // Whether samples that hit must bring their first surface: some AOV beyond alpha, the sample
  // count and the variance is asked for.
  bool records_surfaces() const { return records_surfaces_; }
  bool records_occlusion() const { return !frame_.ambient_occlusion.empty(); }

  // One sample's radiance, counted in the pixel's samples; `second_half`: it also counts in
  // adaptive sampling's second estimate. False, and nothing added, when it is NaN or infinite.
  bool add_radiance(PixelSums& sums, const glm::vec3& radiance, bool second_half) const {
    ++sums.samples;
    if (!is_finite(radiance)) return false;
    sums.color += glm::dvec3(radiance);
    if (records_variance_) {
      const double l = matbase::rec709_luminance(radiance);
      sums.luminance_squares += l * l;
    }
    if (second_half) sums.second_estimate += glm::dvec3(radiance);
    return true;
  }

  // `count` samples of the same radiance: what add_radiance sums for them, the colour still
  // added sample by sample so that it rounds alike. With `second_estimate`, the k-th of them
  // counts in the second estimate where in_second_half(k). False, and only the samples counted,
  // when the radiance is NaN or infinite.
  template <class InSecondHalf>
  bool add_repeated_radiance(PixelSums& sums, const glm::vec3& radiance, uint32_t count, bool second_estimate,
                             InSecondHalf&& in_second_half) const {
    sums.samples += count;
    if (!is_finite(radiance)) return false;
    const glm::dvec3 value(radiance);
    for (uint32_t k = 0; k < count; ++k) sums.color += value;
    if (records_variance_) {
      const double l = matbase::rec709_luminance(radiance);
      for (uint32_t k = 0; k < count; ++k) sums.luminance_squares += l * l;
    }
    if (second_estimate)
      for (uint32_t k = 0; k < count; ++k)
        if (in_second_half(k)) sums.second_estimate += value;
    return true;
  }

  // The fraction of the camera ray that reached no surface.
  static void add_transparency(PixelSums& sums, float transparency) {
    sums.coverage += 1.0 - static_cast<double>(transparency);
  }

  // A sample that hit `sp`: the surface's material parameters and normals into pixel `pixel`'s sums.
  void add_surface(PixelSums& sums, size_t pixel, const SurfacePoint& sp) {
    for (const matmaterial::MaterialParameterInfo* info : parameter_aovs_) {
      const glm::vec3 value =
          glm::clamp(sp.inputs.color(info->id), static_cast<float>(info->min), static_cast<float>(info->max));
      std::vector<float>& sum = frame_.parameter(info->id);
      if (info->kind == matmaterial::ParameterKind::Color) {
        for (int c = 0; c < 3; ++c) sum[3 * pixel + c] += value[c];
      } else {
        sum[pixel] += value.x;  // a scalar reads x
      }
    }
    sums.normal += sp.shading_normal;
    if (!frame_.normal_tangent.empty())
      for (int c = 0; c < 3; ++c) frame_.normal_tangent[3 * pixel + c] += sp.tangent_space_normal[c];
  }

  // Depth, label, part and object come from the hit nearest the pixel centre, never blended:
  // whether a hit at squared distance offset2 from it is nearer than those so far, and keeping it.
  static bool nearer_than_kept(const PixelSums& sums, float offset2) { return offset2 < sums.nearest_offset2; }
  static void keep_nearest(PixelSums& sums, float offset2, float depth, int32_t label, int32_t part, int32_t object) {
    sums.nearest_offset2 = offset2;
    sums.depth = depth;
    sums.label = label;
    sums.part = part;
    sums.object = object;
  }

  // Turns pixel `pixel`'s sums into its values, and adds its ambient occlusion's error to `figures`.
  void resolve(size_t pixel, const PixelSums& sums, OcclusionFigures& figures);

 private:
  FrameBuffers& frame_;
  glm::mat3 world_to_camera_;
  bool records_surfaces_;
  bool records_variance_;
  std::vector<const matmaterial::MaterialParameterInfo*> parameter_aovs_;
};

}  // namespace matrender
