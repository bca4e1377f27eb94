#include "matrender/render.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include "film/adaptive_sampling.h"
#include "film/camera_rays.h"
#include "film/pixel_filter.h"
#include "film/reachable_pixels.h"
#include "integrator/ambient_occlusion.h"
#include "integrator/path_tracer.h"
#include "lights/light_sampler.h"
#include "matbase/image/srgb.h"
#include "matbase/memory_limit.h"
#include "matbase/pi.h"
#include "matbase/threads.h"
#include "matrender/denoise.h"
#include "matrender/scene_limits.h"
#include "sampling/pixel_sampler.h"
#include "scene/scene_data.h"
#include "texture/texel_cache.h"
#include "util/finite.h"

namespace matrender {
namespace {

constexpr int kTileSize = 16;

struct Tile {
  int x0, y0, x1, y1;
};

std::vector<Tile> make_tiles(int width, int height) {
  std::vector<Tile> tiles;
  for (int y = 0; y < height; y += kTileSize)
    for (int x = 0; x < width; x += kTileSize)
      tiles.push_back({x, y, std::min(x + kTileSize, width), std::min(y + kTileSize, height)});
  return tiles;
}

// What one pixel accumulates over its samples, beside the sums of its material parameters and
// tangent-space normal, which accumulate in the frame's own arrays (render_samples). With
// adaptive sampling it is kept between the rounds of samples, so it stays small.
struct PixelAccumulator {
  glm::dvec3 color{0.0};
  glm::dvec3 second_estimate{0.0};  // adaptive sampling: the colour of the samples of its second half
  double luminance_squares = 0.0;    // summed squared Rec.709 luminance of the samples, for the variance
  double coverage = 0.0;  // summed 1 - transparency of the camera rays
  OcclusionTally occlusion;
  OcclusionSite last_hit;  // where occlusion rays the pixel still misses at the end start
  glm::vec3 normal{0.0f};
  uint32_t samples = 0;
  int32_t hits = 0;
  float nearest_offset2 = std::numeric_limits<float>::infinity();
  float depth = 0.0f;
  int32_t label = 0;
  int32_t part = -1;
};

// The AOVs a render fills: those asked for, and the denoiser's guides when it runs.
uint32_t rendered_aovs(const RenderSettings& settings) {
  return settings.aovs | (settings.denoise ? kDenoiseGuideAovs : 0u);
}

void validate(const Camera& camera, const RenderSettings& settings) {
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
  const double pixels = static_cast<double>(camera.width) * static_cast<double>(camera.height);
  const bool adaptive = settings.noise_threshold > 0.0;
  matbase::require_memory(FrameBuffers::bytes_for(camera.width, camera.height, rendered_aovs(settings)) +
                              (adaptive ? pixels * (sizeof(PixelAccumulator) + 1) : 0.0),
                          std::string(adaptive ? "the colour and AOV buffers and adaptive sampling's sums" : "the colour and AOV buffers") +
                              " of a " + std::to_string(camera.width) + " x " + std::to_string(camera.height) + " image",
                          "render");
}

}  // namespace

int fewest_samples_per_pixel(const RenderSettings& settings) {
  const std::optional<AdaptiveSampling> adaptive =
      AdaptiveSampling::from_settings(settings.noise_threshold, settings.min_samples);
  if (!adaptive) return settings.samples_per_pixel;
  return static_cast<int>(std::min<int64_t>(settings.samples_per_pixel, adaptive->next_check(0)));
}

RenderStats render(Scene& scene, const Camera& camera, const RenderSettings& settings, FrameBuffers& frame) {
  validate(camera, settings);
  const auto start = std::chrono::steady_clock::now();
  scene.commit();
  const SceneData& data = scene.data();
  std::vector<PreparedMeshEmitter> emitters;
  for (uint32_t mesh = 0; mesh < data.meshes.size(); ++mesh)
    if (std::optional<PreparedMeshEmitter> emitter = PreparedMeshEmitter::of_mesh(data, mesh))
      emitters.push_back(std::move(*emitter));
  // Cycles' biased estimators (the clearcoat's) converge to an image that depends on the MIS
  // weights, so parity picks lights as Cycles does too.
  const LightSelection selection = settings.cycles_parity ? LightSelection::Uniform : settings.light_selection;
  const LightSampler lights(data.lights, data.world, selection, emitters);
  const CameraRays rays(camera);
  // Cycles 3.4 on the CPU does not mip-map: parity looks textures up bilinearly.
  const bool mipmaps = settings.mipmaps && !settings.cycles_parity;
  const PathTracer tracer(data, lights,
                          {settings.max_bounces, settings.max_diffuse_bounces, settings.max_glossy_bounces,
                           settings.max_transmission_bounces, settings.max_transparent_bounces,
                           settings.transparent_background,
                           settings.cycles_parity ? ClearcoatEstimator::Cycles34 : ClearcoatEstimator::Integral,
                           settings.cycles_parity ? MultiscatterWalk::Cycles34 : MultiscatterWalk::Exact,
                           mipmaps ? rays.pixel_spread_angle() : 0.0f});
  const PixelFilterSampler& filter = blackman_harris_sampler();
  // Camera rays of pixels outside it meet nothing: they see the background (and lamps visible to
  // the camera, which lie outside the vertices' box).
  const PixelRect pixels_seeing_scene =
      lights.has_camera_visible_lamps()
          ? PixelRect{0, 0, camera.width, camera.height}
          : pixels_seeing_box(rays, camera.width, camera.height, data.vertex_lower, data.vertex_upper);
  // What every camera ray that meets nothing sees, when it does not depend on the direction: the
  // samples of a pixel outside pixels_seeing_scene then need no ray at all.
  const std::optional<glm::vec3> uniform_background =
      settings.transparent_background ? std::optional<glm::vec3>(glm::vec3(0.0f)) : lights.uniform_camera_background();
  const glm::mat3 world_to_camera = glm::transpose(glm::mat3(rays.right(), rays.up(), rays.back()));

  const std::optional<AdaptiveSampling> adaptive =
      AdaptiveSampling::from_settings(settings.noise_threshold, settings.min_samples);

  const uint32_t aovs = rendered_aovs(settings);
  frame.resize(camera.width, camera.height, aovs);
  frame.transparent_background = settings.transparent_background;
  const std::vector<Tile> tiles = make_tiles(camera.width, camera.height);
  const size_t pixel_count = static_cast<size_t>(camera.width) * static_cast<size_t>(camera.height);
  std::atomic<uint64_t> ray_count{0}, discarded{0}, samples{0}, sample_slots{0};
  std::atomic<bool> cancelled{false};
  const uint32_t spp = static_cast<uint32_t>(settings.samples_per_pixel);
  // Progress counts sample slots: a sample taken, or one a converged pixel skips.
  const uint64_t total_slots = static_cast<uint64_t>(pixel_count) * spp;
  // Progress is reported every kProgressSamples slots a thread passes, not per tile: at millions
  // of samples per pixel one tile takes minutes.
  constexpr uint64_t kProgressSamples = 1u << 16;
  std::mutex progress_mutex;
  double reported_fraction = 0.0;
  auto count_slots = [&](uint64_t new_slots) {
    const uint64_t done = sample_slots.fetch_add(new_slots) + new_slots;
    if (!settings.progress) return;
    std::lock_guard<std::mutex> lock(progress_mutex);
    const double fraction = static_cast<double>(done) / static_cast<double>(total_slots);
    if (fraction <= reported_fraction) return;
    reported_fraction = fraction;
    settings.progress(fraction);
  };
  // Checked at every packet of samples, so that a cancel takes effect within milliseconds.
  auto cancel_requested = [&] {
    if (cancelled.load(std::memory_order_relaxed)) return true;
    if (!settings.cancel || !settings.cancel->load(std::memory_order_relaxed)) return false;
    cancelled = true;
    return true;
  };
  // Without AOVs beyond alpha and the sample count a pixel only counts its hits.
  const bool surface_aovs = (aovs & ~static_cast<uint32_t>(AovAlpha | AovSampleCount | AovColorVariance)) != 0;
  std::vector<const matmaterial::MaterialParameterInfo*> parameter_aovs;
  for (const matmaterial::MaterialParameterInfo& info : matmaterial::kMaterialParameters)
    if (aovs & parameter_aov(info.id)) parameter_aovs.push_back(&info);
  const bool ambient_occlusion = (aovs & AovAmbientOcclusion) != 0;
  const bool color_variance = (aovs & AovColorVariance) != 0;
  const double occlusion_error = settings.ambient_occlusion_error;
  const float occlusion_distance = static_cast<float>(settings.ambient_occlusion_distance);

  // What one tile's thread counts before adding it to the render's totals.
  struct TileCounts {
    uint64_t rays = 0, discarded = 0, samples = 0, uncounted_slots = 0;
    // Over the pixels finished, for RenderStats' occlusion figures.
    double occlusion_squared_error = 0.0, occlusion_max_error = 0.0;
    uint64_t occlusion_pixels = 0;
  };
  // Each tile's occlusion figures, summed in tile order at the end so they do not depend on
  // which thread finished first.
  std::vector<TileCounts> tile_occlusion(tiles.size());
  auto pass_slots = [&](TileCounts& counts, uint64_t slots) {
    counts.uncounted_slots += slots;
    if (counts.uncounted_slots < kProgressSamples) return;
    count_slots(counts.uncounted_slots);
    counts.uncounted_slots = 0;
  };

  // Whether camera sample `sample` of the pixel with `seeds` counts in adaptive sampling's
  // second estimate.
  auto in_second_half = [&](uint32_t sample, const PixelSeeds& seeds) {
    return in_second_estimate(shuffled_sobol_index(reverse_bits(sample), seeds.pair(0)));
  };

  // Adds the radiance of camera sample `sample` of the pixel with `seeds` to acc.
  auto add_radiance = [&](const glm::vec3& radiance, uint32_t sample, const PixelSeeds& seeds, PixelAccumulator& acc,
                          TileCounts& counts) {
    ++acc.samples;
    if (!is_finite(radiance)) {
      ++counts.discarded;
      return;
    }
    acc.color += glm::dvec3(radiance);
    if (color_variance) {
      const double l = matbase::rec709_luminance(radiance);
      acc.luminance_squares += l * l;
    }
    if (adaptive && in_second_half(sample, seeds)) acc.second_estimate += glm::dvec3(radiance);
  };

  // Samples [begin, end) of a pixel whose camera rays all meet nothing and see a uniform
  // background: what render_samples would sum for them, without their rays.
  // Every sample adds the same radiance: add_radiance's sums, with what does not change from
  // sample to sample worked out once (most of an object's frame is background: the textured
  // vase takes 3 % fewer instructions per sample). The colour is still added sample by sample,
  // so its sum rounds as render_samples' does.
  auto add_background_samples = [&](uint32_t pixel_index, uint32_t begin, uint32_t end, PixelAccumulator& acc,
                                    TileCounts& counts) {
    const PixelSeeds seeds(pixel_index, settings.seed);
    const bool finite = is_finite(*uniform_background);
    const glm::dvec3 radiance(*uniform_background);
    const double luminance = matbase::rec709_luminance(*uniform_background);
    for (uint32_t first = begin; first < end; first += kPacketSamples) {
      if (cancel_requested()) return;
      const uint32_t count = std::min<uint32_t>(kPacketSamples, end - first);
      counts.samples += count;
      pass_slots(counts, count);
      acc.samples += count;
      // Each sample covers nothing (the background shows through whole).
      if (!finite) {
        counts.discarded += count;
        continue;
      }
      for (uint32_t k = 0; k < count; ++k) acc.color += radiance;
      if (color_variance)
        for (uint32_t k = 0; k < count; ++k) acc.luminance_squares += luminance * luminance;
      if (adaptive)
        for (uint32_t sample = first; sample < first + count; ++sample)
          if (in_second_half(sample, seeds)) acc.second_estimate += radiance;
    }
  };

  // Takes samples [begin, end) of pixel (x, y) into acc; the material parameters and the
  // tangent-space normal are summed into the frame's arrays.
  auto render_samples = [&](int x, int y, uint32_t begin, uint32_t end, PixelAccumulator& acc, TileCounts& counts) {
    const uint32_t pixel_index = static_cast<uint32_t>(y) * static_cast<uint32_t>(camera.width) + static_cast<uint32_t>(x);
    const bool sees_scene = pixels_seeing_scene.contains(x, y);
    if (!sees_scene && uniform_background) {
      add_background_samples(pixel_index, begin, end, acc, counts);
      return;
    }
    const size_t i = pixel_index;
    const PixelSeeds seeds(pixel_index, settings.seed);
    const PairSeeds occlusion_seeds = ambient_occlusion_seeds(pixel_index, settings.seed);
    static_assert(kPacketSamples == EmbreeScene::kPacketSize, "one sample packet per camera-ray packet");
    glm::vec2 offsets[kPacketSamples];
    glm::vec3 dirs[kPacketSamples];
    RayHit camera_hits[kPacketSamples];
    // The surface each camera ray hits, for the AOVs; made once per pixel, filled by trace.
    SurfacePoint sp;
    for (uint32_t first = begin; first < end; first += kPacketSamples) {
      if (cancel_requested()) return;
      const int count = static_cast<int>(std::min<uint32_t>(kPacketSamples, end - first));
      counts.samples += static_cast<uint64_t>(count);
      pass_slots(counts, static_cast<uint64_t>(count));
      const SamplePacket packet(seeds, first);
      for (int lane = 0; lane < count; ++lane) {
        offsets[lane] = filter.sample(packet.point(0, lane));
        dirs[lane] = rays.direction(static_cast<float>(x) + 0.5f + offsets[lane].x,
                                    static_cast<float>(y) + 0.5f + offsets[lane].y);
      }
      if (sees_scene) {
        data.accel.intersect_coherent(rays.origin(), dirs, count, camera_hits);
        counts.rays += static_cast<uint64_t>(count);
      } else {
        std::fill(camera_hits, camera_hits + count, RayHit());
      }
      for (int lane = 0; lane < count; ++lane) {
        const uint32_t sample = first + static_cast<uint32_t>(lane);
        const PathResult path = tracer.trace(rays.origin(), dirs[lane], camera_hits[lane], PixelSampler(packet, lane),
                                             surface_aovs ? &sp : nullptr);
        counts.rays += path.rays;
        add_radiance(path.radiance, sample, seeds, acc, counts);
        acc.coverage += 1.0 - static_cast<double>(path.transparency);
        if (!path.hit) continue;
        ++acc.hits;
        if (!surface_aovs) continue;
        for (const matmaterial::MaterialParameterInfo* info : parameter_aovs) {
          const glm::vec3 value =
              glm::clamp(sp.inputs.color(info->id), static_cast<float>(info->min), static_cast<float>(info->max));
          std::vector<float>& sum = frame.parameter(info->id);
          if (info->kind == matmaterial::ParameterKind::Color) {
            for (int c = 0; c < 3; ++c) sum[3 * i + c] += value[c];
          } else {
            sum[i] += value.x;  // a scalar reads x
          }
        }
        acc.normal += sp.shading_normal;
        if (!frame.normal_tangent.empty())
          for (int c = 0; c < 3; ++c) frame.normal_tangent[3 * i + c] += sp.tangent_space_normal[c];
        if (ambient_occlusion) {
          acc.last_hit = OcclusionSite::of(sp);
          const int rays_now = occlusion_error > 0.0
                                   ? occlusion_rays_per_hit(acc.occlusion, acc.samples, static_cast<uint32_t>(acc.hits),
                                                            end - sample, occlusion_error)
                                   : settings.ambient_occlusion_rays;
          uint32_t occlusion_rays_traced = 0;
          trace_occlusion_rays(data.accel, acc.last_hit, occlusion_distance, occlusion_seeds, rays_now, acc.occlusion,
                               &occlusion_rays_traced);
          counts.rays += occlusion_rays_traced;
        }
        const float offset2 = glm::dot(offsets[lane], offsets[lane]);
        if (offset2 < acc.nearest_offset2) {
          acc.nearest_offset2 = offset2;
          acc.depth = path.first_distance * glm::dot(dirs[lane], rays.forward());
          acc.label = data.materials[sp.material].label_id;
          acc.part = sp.part;
        }
      }
    }
    if (ambient_occlusion && occlusion_error > 0.0 && acc.hits > 0) {
      uint32_t occlusion_rays_traced = 0;
      top_up_occlusion(data.accel, acc.last_hit, occlusion_distance, occlusion_seeds, occlusion_error, acc.occlusion,
                       &occlusion_rays_traced);
      counts.rays += occlusion_rays_traced;
    }
  };

  // Turns pixel i's sums into its values.
  auto finish_pixel = [&](size_t i, const PixelAccumulator& acc, TileCounts& counts) {
    if (!frame.sample_count.empty()) frame.sample_count[i] = static_cast<int32_t>(acc.samples);
    if (acc.samples == 0) return;  // cancelled before it began
    const double inv_samples = 1.0 / static_cast<double>(acc.samples);
    const glm::dvec3 color = acc.color * inv_samples;
    for (int c = 0; c < 3; ++c) frame.color[3 * i + c] = static_cast<float>(color[c]);
    if (!frame.alpha.empty()) frame.alpha[i] = static_cast<float>(acc.coverage * inv_samples);
    if (!frame.color_variance.empty() && acc.samples > 1) {
      // The unbiased sample variance over n, the variance of the mean.
      const double mean = matbase::rec709_luminance(color);
      const double spread = std::max(0.0, acc.luminance_squares * inv_samples - mean * mean);
      frame.color_variance[i] = static_cast<float>(spread / (static_cast<double>(acc.samples) - 1.0));
    }
    if (acc.hits == 0) return;
    const float inv_hits = 1.0f / static_cast<float>(acc.hits);
    const float normal_len = glm::length(acc.normal);
    const glm::vec3 normal = normal_len > 0.0f ? acc.normal / normal_len : glm::vec3(0.0f);
    const glm::vec3 normal_camera = world_to_camera * normal;
    for (const matmaterial::MaterialParameterInfo* info : parameter_aovs) {
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
          acc.occlusion.trials > 0 ? static_cast<float>(static_cast<double>(acc.occlusion.escaped) / acc.occlusion.trials)
                                   : 0.0f;
      const double error = acc.occlusion.standard_error();
      counts.occlusion_squared_error += error * error;
      counts.occlusion_max_error = std::max(counts.occlusion_max_error, error);
      ++counts.occlusion_pixels;
    }
    if (!frame.depth.empty()) frame.depth[i] = acc.depth;
    if (!frame.label.empty()) frame.label[i] = acc.label;
    if (!frame.part_id.empty()) frame.part_id[i] = acc.part;
  };

  tbb::task_arena arena(matbase::worker_threads(settings.threads));
  // Runs `visit_pixel(x, y, i, counts)` over the image, a tile per task. Tiles are handed out
  // one at a time (simple_partitioner): most of a frame's cost sits in the few tiles the object
  // covers, since pixels that cannot see it take no rays, and TBB's default chunks of tiles left
  // one thread finishing alone (the textured vase at 64 spp: 1.72 x one thread's speed on 2
  // threads, 1.80 x with single tiles; render_bench).
  auto for_each_pixel = [&](const auto& visit_pixel) {
    arena.execute([&] {
      tbb::parallel_for(tbb::blocked_range<size_t>(0, tiles.size(), 1), [&](const tbb::blocked_range<size_t>& range) {
        for (size_t t = range.begin(); t != range.end(); ++t) {
          if (cancel_requested()) return;
          const Tile& tile = tiles[t];
          TileCounts counts;
          for (int y = tile.y0; y < tile.y1; ++y)
            for (int x = tile.x0; x < tile.x1; ++x)
              visit_pixel(x, y, static_cast<size_t>(y) * static_cast<size_t>(camera.width) + static_cast<size_t>(x),
                          counts);
          ray_count += counts.rays;
          discarded += counts.discarded;
          samples += counts.samples;
          count_slots(counts.uncounted_slots);
          tile_occlusion[t].occlusion_squared_error += counts.occlusion_squared_error;
          tile_occlusion[t].occlusion_max_error = std::max(tile_occlusion[t].occlusion_max_error, counts.occlusion_max_error);
          tile_occlusion[t].occlusion_pixels += counts.occlusion_pixels;
          // So that the texture levels the cache has dropped meanwhile are freed.
          release_pinned_texels();
        }
      }, tbb::simple_partitioner());
    });
  };

  if (!adaptive) {
    for_each_pixel([&](int x, int y, size_t i, TileCounts& counts) {
      PixelAccumulator acc;
      render_samples(x, y, 0, spp, acc, counts);
      finish_pixel(i, acc, counts);
    });
  } else {
    // Rounds of samples for the whole image, each up to the next check; pixels the check finds
    // converged skip the rounds after it (docs/conventions.md, "Adaptive sampling").
    std::vector<PixelAccumulator> accumulators(pixel_count);
    std::vector<uint8_t> converged(pixel_count, 0);
    for (uint32_t begin = 0; begin < spp && !cancelled;) {
      const uint32_t end = std::min(spp, adaptive->next_check(begin));
      for_each_pixel([&](int x, int y, size_t i, TileCounts& counts) {
        if (converged[i])
          pass_slots(counts, end - begin);
        else
          render_samples(x, y, begin, end, accumulators[i], counts);
      });
      if (end < spp) {
        for (size_t i = 0; i < pixel_count; ++i)
          if (!converged[i])
            converged[i] = pixel_converged(accumulators[i].color, accumulators[i].second_estimate,
                                           accumulators[i].samples, adaptive->error_bound());
        keep_neighbours_sampling(converged, camera.width, camera.height);
      }
      begin = end;
    }
    for_each_pixel([&](int, int, size_t i, TileCounts& counts) { finish_pixel(i, accumulators[i], counts); });
  }

  if (settings.denoise && !cancelled) {
    DenoiseSettings denoising;
    denoising.threads = settings.threads;
    denoise(frame, denoising);
  }

  RenderStats stats;
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  stats.camera_samples = samples;
  stats.rays = ray_count;
  stats.discarded_samples = discarded;
  stats.cancelled = cancelled;
  double occlusion_squared_error = 0.0;
  uint64_t occlusion_pixels = 0;
  for (const TileCounts& tile : tile_occlusion) {
    occlusion_squared_error += tile.occlusion_squared_error;
    occlusion_pixels += tile.occlusion_pixels;
    stats.occlusion_max_standard_error = std::max(stats.occlusion_max_standard_error, tile.occlusion_max_error);
  }
  if (occlusion_pixels > 0) stats.occlusion_rms_standard_error = std::sqrt(occlusion_squared_error / occlusion_pixels);
  return stats;
}

}  // namespace matrender
