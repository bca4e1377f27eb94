#include "matrender/render.h"

#include <chrono>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "film/adaptive_sampling.h"
#include "film/camera_rays.h"
#include "film/denoised_error.h"
#include "film/error_target.h"
#include "film/film.h"
#include "film/pixel_filter.h"
#include "film/reachable_pixels.h"
#include "integrator/ambient_occlusion.h"
#include "integrator/path_tracer.h"
#include "integrator/pixel_evaluator.h"
#include "integrator/render_control.h"
#include "integrator/render_statistics.h"
#include "integrator/tile_schedule.h"
#include "lights/light_sampler.h"
#include "matbase/memory_limit.h"
#include "matbase/pi.h"
#include "matrender/denoiser.h"
#include "matrender/scene_limits.h"
#include "scene/scene_data.h"
#include "texture/texel_cache.h"
#include "util/finite.h"

namespace matrender {
namespace {

// The AOVs a render fills: those asked for, and the denoiser's guides when one runs.
uint32_t rendered_aovs(const RenderSettings& settings, const Denoiser* denoiser) {
  return settings.aovs | (denoiser ? denoiser->guide_aovs() : 0u);
}

// The denoiser the settings name, refused as render's own when the program has none.
std::shared_ptr<const Denoiser> render_denoiser(const RenderSettings& settings) {
  try {
    return denoiser_for(settings.denoise);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("render: ") + e.what());
  }
}

// Everything a render is given, checked before any work: the camera and the settings (their
// declarations).
void check_render(const Camera& camera, const RenderSettings& settings) {
  if (camera.width < 1 || camera.height < 1)
    throw std::invalid_argument("render: image size must be at least 1 x 1, got " +
                                std::to_string(camera.width) + " x " + std::to_string(camera.height));
  if (!is_finite(camera.camera_to_world))
    throw std::invalid_argument("render: the camera's camera-to-world matrix has a non-finite entry");
  check_scene_point(glm::dvec3(camera.camera_to_world[3]), "render: the camera");
  if (!(camera.vertical_fov > 0.0 && camera.vertical_fov < matbase::kPi))
    throw std::invalid_argument("render: vertical field of view must be in (0, pi) radians");
  if (const std::optional<std::string> problem = render_settings_problem(settings))
    throw std::invalid_argument("render: " + *problem);
}

// The memory the frame needs, with the AOVs the denoiser reads.
void check_frame_memory(const Camera& camera, const RenderSettings& settings, const Denoiser* denoiser) {
  const double pixels = static_cast<double>(camera.width) * static_cast<double>(camera.height);
  // Adaptive sampling keeps every pixel's sums and a converged flag, a target error its sums and
  // its sample count for the next round.
  // With a denoiser, a target error also denoises the two halves (film/denoised_error.h).
  const double halves = denoiser ? denoised_error_bytes_per_pixel(*denoiser) : 0.0;
  const double per_pixel = settings.target_error > 0.0      ? sizeof(PixelSums) + sizeof(uint32_t) + halves
                           : settings.noise_threshold > 0.0 ? sizeof(PixelSums) + 1
                                                            : 0.0;
  matbase::require_memory(FrameBuffers::bytes_for(camera.width, camera.height, rendered_aovs(settings, denoiser)) +
                              pixels * per_pixel,
                          std::string(per_pixel > 0.0 ? "the colour and AOV buffers and every pixel's sums" : "the colour and AOV buffers") +
                              " of a " + std::to_string(camera.width) + " x " + std::to_string(camera.height) + " image",
                          "render");
}

// The filters run on the finished frame: the denoiser when asked for.
void apply_post_filters(const RenderSettings& settings, const Denoiser* denoiser, FrameBuffers& frame) {
  if (denoiser) denoiser->denoise(frame, settings.threads);
}

// Runs visit_pixel(x, y, index, counts, progress) over every pixel of the image, a tile per task,
// each tile's counts added to its own in `tile_counts`.
template <class VisitPixel>
void for_each_pixel(TileSchedule& schedule, RenderControl& control, int width, std::vector<SampleCounts>& tile_counts,
                    const VisitPixel& visit_pixel) {
  schedule.run([&control] { return control.cancelled(); },
               [&](size_t t, const Tile& tile) {
                 SampleCounts counts;
                 RenderControl::Batch progress;
                 for (int y = tile.y0; y < tile.y1; ++y)
                   for (int x = tile.x0; x < tile.x1; ++x)
                     visit_pixel(x, y, static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x),
                                 counts, progress);
                 tile_counts[t].add(counts);
                 control.report(progress);
                 // So that the texture levels the cache has dropped meanwhile are freed.
                 release_pinned_texels();
               });
}

// With a target error, the most samples a pixel takes and those every pixel takes before the
// error is first checked: powers of two (film/error_target.h), at least 2.
uint32_t error_target_cap(const RenderSettings& settings) {
  return std::max<uint32_t>(2, power_of_two_at_most(static_cast<uint32_t>(settings.samples_per_pixel)));
}
uint32_t error_target_first_round(const RenderSettings& settings) {
  constexpr uint32_t kDefaultFirstRound = 16;
  const uint32_t asked = settings.min_samples > 0 ? static_cast<uint32_t>(settings.min_samples) : kDefaultFirstRound;
  return std::min(std::max<uint32_t>(2, power_of_two_at_most(asked)), error_target_cap(settings));
}

// What a target error is for: the frame as sampled, or the frame a denoiser will make of it.
struct ErrorTargetFrame {
  const Denoiser* denoiser;       // nullptr: none
  const FrameBuffers& accumulating;  // the film's frame, for the denoiser's guides
  glm::mat3 world_to_camera;
};

// Samples every pixel to the target error in rounds (film/error_target.h, film/denoised_error.h);
// returns the predicted error, of the denoised frame with a denoiser, when sampling stopped.
// Pixels no surface covers stop after the first round unless they are beside covered ones; the
// samples pixels did not take are passed for the progress.
double sample_to_target_error(const RenderSettings& settings, const ErrorTargetFrame& target_frame,
                              TileSchedule& schedule, RenderControl& control, const PixelEvaluator& evaluator,
                              Film& film, int width, int height, std::vector<SampleCounts>& tile_counts) {
  const size_t pixel_count = static_cast<size_t>(width) * static_cast<size_t>(height);
  const uint32_t cap = error_target_cap(settings);
  std::vector<PixelSums> sums(pixel_count);
  std::vector<uint32_t> counts(pixel_count, error_target_first_round(settings));
  // A pixel doubling from n to 2n keeps the sum of its first n, its first half.
  const auto take_to = [&](int x, int y, size_t i, uint32_t end, SampleCounts& tile, RenderControl::Batch& progress) {
    evaluator.take_samples(x, y, sums[i].samples, end, sums[i], tile, progress);
  };
  for_each_pixel(schedule, control, width, tile_counts,
                 [&](int x, int y, size_t i, SampleCounts& tile, RenderControl::Batch& progress) {
                   take_to(x, y, i, counts[i] / 2, tile, progress);
                   keep_first_half(sums[i]);
                   take_to(x, y, i, counts[i], tile, progress);
                 });
  // The target of the next round's plan, which predicts the undenoised frame's error: with a
  // denoiser, the target scaled by what denoising takes off the prediction now; nothing once the
  // denoised prediction meets the target.
  double predicted_error = 0.0;
  const auto plan_target = [&]() -> std::optional<double> {
    const FrameErrorEstimate raw = predict_frame_error(sums);
    if (!target_frame.denoiser) {
      predicted_error = raw.relative_rmse;
      return settings.target_error;
    }
    predicted_error = predict_denoised_error(sums, raw, target_frame.accumulating, *target_frame.denoiser,
                                             target_frame.world_to_camera, settings.threads)
                          .relative_rmse;
    if (predicted_error <= settings.target_error) return std::nullopt;
    return settings.target_error * raw.relative_rmse / predicted_error;
  };
  for (std::optional<double> target = plan_target();
       target && !control.was_cancelled() && plan_error_target_round(sums, width, height, *target, cap, counts);
       target = plan_target())
    for_each_pixel(schedule, control, width, tile_counts,
                   [&](int x, int y, size_t i, SampleCounts& tile, RenderControl::Batch& progress) {
                     if (counts[i] == sums[i].samples) return;
                     keep_first_half(sums[i]);
                     take_to(x, y, i, counts[i], tile, progress);
                   });
  for_each_pixel(schedule, control, width, tile_counts, [&](int, int, size_t i, SampleCounts& tile, RenderControl::Batch& progress) {
    control.pass(progress, static_cast<uint64_t>(settings.samples_per_pixel) - std::min<uint64_t>(sums[i].samples, settings.samples_per_pixel));
    film.resolve(i, sums[i], tile.occlusion);
  });
  return predicted_error;
}

}  // namespace

int fewest_samples_per_pixel(const RenderSettings& settings) {
  if (settings.target_error > 0.0) return static_cast<int>(error_target_first_round(settings));
  const std::optional<AdaptiveSampling> adaptive =
      AdaptiveSampling::from_settings(settings.noise_threshold, settings.min_samples);
  if (!adaptive) return settings.samples_per_pixel;
  return static_cast<int>(std::min<int64_t>(settings.samples_per_pixel, adaptive->next_check(0)));
}

RenderStats render(Scene& scene, const Camera& camera, const RenderSettings& settings, FrameBuffers& frame) {
  check_render(camera, settings);
  const std::shared_ptr<const Denoiser> denoiser = render_denoiser(settings);
  check_frame_memory(camera, settings, denoiser.get());
  const auto start = std::chrono::steady_clock::now();
  scene.commit();
  const SceneData& data = scene.data();
  // Cycles' biased estimators (the clearcoat's) converge to an image that depends on the MIS
  // weights, so parity picks lights as Cycles does too.
  const LightSampler lights =
      LightSampler::for_scene(data, settings.cycles_parity ? LightSelection::Uniform : settings.light_selection);
  const CameraRays rays(camera);
  const PathTracer tracer(data, lights, PathSettings(settings, rays.pixel_spread_angle()));
  const glm::mat3 world_to_camera = glm::transpose(glm::mat3(rays.right(), rays.up(), rays.back()));
  Film film(frame, camera.width, camera.height, rendered_aovs(settings, denoiser.get()), settings.transparent_background,
            world_to_camera);
  const std::optional<AdaptiveSampling> adaptive =
      AdaptiveSampling::from_settings(settings.noise_threshold, settings.min_samples);
  const uint32_t spp = static_cast<uint32_t>(settings.samples_per_pixel);
  const size_t pixel_count = static_cast<size_t>(camera.width) * static_cast<size_t>(camera.height);
  RenderControl control(settings, static_cast<uint64_t>(pixel_count) * spp);
  const AmbientOcclusionEstimator occlusion(data.accel, static_cast<float>(settings.ambient_occlusion_distance),
                                            settings.ambient_occlusion_error, settings.ambient_occlusion_rays);
  // The pixel filter of the settings' width; Blender's default one is made once for every render.
  const std::optional<PixelFilterSampler> own_filter =
      settings.filter_width == PixelFilterSampler::kDefaultRadius ? std::nullopt
                                                                  : std::optional<PixelFilterSampler>(settings.filter_width);
  const PixelFilterSampler& filter = own_filter ? *own_filter : blackman_harris_sampler();
  // Camera rays of pixels outside the box's image meet nothing: they see the background (and
  // lamps visible to the camera, which lie outside the vertices' box). When what they see does
  // not depend on the direction, their samples need no ray at all.
  const PixelRect pixels_seeing_scene =
      lights.has_camera_visible_lamps()
          ? PixelRect{0, 0, camera.width, camera.height}
          : pixels_seeing_box(rays, camera.width, camera.height, data.vertex_lower, data.vertex_upper, filter.radius());
  const std::optional<glm::vec3> uniform_background =
      settings.transparent_background ? std::optional<glm::vec3>(glm::vec3(0.0f)) : lights.uniform_camera_background();
  const PixelEvaluator evaluator({data, tracer, rays, filter, camera.width, settings.seed, pixels_seeing_scene,
                                  uniform_background, adaptive.has_value(),
                                  film.records_occlusion() ? &occlusion : nullptr},
                                 film, control);

  TileSchedule schedule(camera.width, camera.height, settings.threads);
  std::vector<SampleCounts> tile_counts(schedule.tiles().size());
  double predicted_error = 0.0;
  if (settings.target_error > 0.0) {
    predicted_error = sample_to_target_error(settings, {denoiser.get(), frame, world_to_camera}, schedule, control,
                                             evaluator, film, camera.width, camera.height, tile_counts);
  } else if (!adaptive) {
    for_each_pixel(schedule, control, camera.width, tile_counts,
                   [&](int x, int y, size_t i, SampleCounts& counts, RenderControl::Batch& progress) {
                     PixelSums sums;
                     evaluator.take_samples(x, y, 0, spp, sums, counts, progress);
                     film.resolve(i, sums, counts.occlusion);
                   });
  } else {
    // Rounds of samples for the whole image, each up to the next check; pixels the check finds
    // converged skip the rounds after it (docs/conventions.md, "Adaptive sampling").
    std::vector<PixelSums> sums(pixel_count);
    std::vector<uint8_t> converged(pixel_count, 0);
    for (uint32_t begin = 0; begin < spp && !control.was_cancelled();) {
      const uint32_t end = std::min(spp, adaptive->next_check(begin));
      for_each_pixel(schedule, control, camera.width, tile_counts,
                     [&](int x, int y, size_t i, SampleCounts& counts, RenderControl::Batch& progress) {
                       if (converged[i])
                         control.pass(progress, end - begin);
                       else
                         evaluator.take_samples(x, y, begin, end, sums[i], counts, progress);
                     });
      if (end < spp) {
        for (size_t i = 0; i < pixel_count; ++i)
          if (!converged[i])
            converged[i] = pixel_converged(sums[i].color, sums[i].second_estimate, sums[i].samples, adaptive->error_bound());
        keep_neighbours_sampling(converged, camera.width, camera.height);
      }
      begin = end;
    }
    for_each_pixel(schedule, control, camera.width, tile_counts,
                   [&](int, int, size_t i, SampleCounts& counts, RenderControl::Batch&) {
                     film.resolve(i, sums[i], counts.occlusion);
                   });
  }
  if (!control.was_cancelled()) apply_post_filters(settings, denoiser.get(), frame);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  RenderStats stats = render_statistics(tile_counts, seconds, control.was_cancelled());
  stats.predicted_error = predicted_error;
  return stats;
}

}  // namespace matrender
