// The stages render() is made of, each on its own: the tile schedule, the progress and cancel of
// a running render, the film's sums and their resolution, one pixel's samples (in one run or in
// adaptive sampling's rounds; with rays or, where nothing can be hit, without), the statistics,
// and the post-filters.
#include <atomic>
#include <cmath>
#include <cstring>
#include <set>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>

#include "film/film.h"
#include "integrator/pixel_evaluator.h"
#include "integrator/render_control.h"
#include "integrator/render_statistics.h"
#include "integrator/tile_schedule.h"
#include "lights/light_sampler.h"
#include "matrender/atrous_filter.h"
#include "matrender/render.h"
#include "matrender/scene.h"
#include "scene/scene_data.h"
#include "test_scenes.h"

using namespace matrender;

TEST_CASE("The tiles cover every pixel once, in tiles of at most 16 x 16", "[render]") {
  for (const auto& [width, height] : {std::pair{1, 1}, {16, 16}, {17, 5}, {40, 33}}) {
    std::vector<int> covered(static_cast<size_t>(width * height), 0);
    for (const Tile& tile : image_tiles(width, height)) {
      CHECK(tile.x1 - tile.x0 <= kTileSize);
      CHECK(tile.y1 - tile.y0 <= kTileSize);
      for (int y = tile.y0; y < tile.y1; ++y)
        for (int x = tile.x0; x < tile.x1; ++x) ++covered[static_cast<size_t>(y * width + x)];
    }
    for (const int count : covered) CHECK(count == 1);
  }
}

TEST_CASE("The schedule visits every tile once on its threads, and none once stopped", "[render]") {
  TileSchedule schedule(70, 50, 2);
  std::vector<std::atomic<int>> visits(schedule.tiles().size());
  schedule.run([] { return false; }, [&](size_t t, const Tile&) { ++visits[t]; });
  for (const std::atomic<int>& count : visits) CHECK(count == 1);
  int after_stop = 0;
  schedule.run([] { return true; }, [&](size_t, const Tile&) { ++after_stop; });
  CHECK(after_stop == 0);
}

TEST_CASE("Progress rises to 1 in batches, and a cancel is seen", "[render]") {
  RenderSettings settings;
  std::vector<double> reported;
  settings.progress = [&reported](double f) { reported.push_back(f); };
  std::atomic<bool> cancel{false};
  settings.cancel = &cancel;
  const uint64_t total = 3 * RenderControl::kProgressSamples;
  RenderControl control(settings, total);
  RenderControl::Batch batch;
  control.pass(batch, RenderControl::kProgressSamples - 1);
  CHECK(reported.empty());  // below a batch: not yet
  control.pass(batch, 1);
  REQUIRE(reported.size() == 1);
  CHECK(reported[0] == Approx(1.0 / 3.0));
  control.pass(batch, 5);
  control.report(batch);  // a tile's end
  control.pass(batch, total - RenderControl::kProgressSamples - 5);
  control.report(batch);
  CHECK(reported.back() == 1.0);
  for (size_t k = 1; k < reported.size(); ++k) CHECK(reported[k] > reported[k - 1]);
  CHECK_FALSE(control.cancelled());
  cancel = true;
  CHECK(control.cancelled());
  cancel = false;
  CHECK(control.was_cancelled());  // once seen, for good
}

TEST_CASE("The film resolves its sums into means: colour, alpha, variance, normals, parameters, nearest hit", "[render]") {
  FrameBuffers frame;
  const uint32_t aovs = default_aovs() | AovColorVariance | AovSampleCount | AovObjectId;
  const glm::mat3 world_to_camera(1.0f);
  Film film(frame, 2, 1, aovs, false, world_to_camera);
  CHECK(film.records_surfaces());
  PixelSums sums;
  const std::vector<glm::vec3> radiance{{1.0f, 2.0f, 3.0f}, {3.0f, 2.0f, 1.0f}, {0.5f, 0.5f, 0.5f}};
  for (const glm::vec3& r : radiance) CHECK(film.add_radiance(sums, r, false));
  CHECK_FALSE(film.add_radiance(sums, glm::vec3(NAN, 0.0f, 0.0f), true));  // counted, adds nothing
  Film::add_transparency(sums, 0.0f);
  Film::add_transparency(sums, 1.0f);
  SurfacePoint sp;
  sp.shading_normal = glm::vec3(0.0f, 0.0f, 1.0f);
  sp.inputs.set(matmaterial::MaterialParameter::Roughness, glm::vec3(0.25f));
  sp.part = 3;
  film.add_surface(sums, 1, sp);
  sp.shading_normal = glm::vec3(1.0f, 0.0f, 0.0f);
  sp.inputs.set(matmaterial::MaterialParameter::Roughness, glm::vec3(2.0f));  // clamped to 1
  sp.part = 4;
  film.add_surface(sums, 1, sp);
  sums.hits = 2;
  REQUIRE(Film::nearer_than_kept(sums, 0.5f));
  Film::keep_nearest(sums, 0.5f, 2.0f, 7, 3, 1);
  CHECK_FALSE(Film::nearer_than_kept(sums, 0.6f));
  OcclusionFigures figures;
  film.resolve(1, sums, figures);
  // Four samples, one discarded (it counts as black).
  CHECK(frame.color[3] == Approx(4.5 / 4.0));
  CHECK(frame.sample_count[1] == 4);
  CHECK(frame.alpha[1] == Approx(1.0 / 4.0));  // one sample covered, one missed, two said nothing
  double squares = 0.0;
  for (const glm::vec3& r : radiance) squares += std::pow(0.2126 * r.x + 0.7152 * r.y + 0.0722 * r.z, 2.0);
  const double mean = 0.2126 * (4.5 / 4.0) + 0.7152 * (4.5 / 4.0) + 0.0722 * (4.5 / 4.0);
  CHECK(frame.color_variance[1] == Approx((squares / 4.0 - mean * mean) / 3.0).epsilon(1e-4));
  CHECK(frame.parameter(matmaterial::MaterialParameter::Roughness)[1] == Approx(0.625f));
  CHECK(frame.normal_world[3] == Approx(std::sqrt(0.5f)));
  CHECK(frame.normal_world[5] == Approx(std::sqrt(0.5f)));
  CHECK(frame.depth[1] == 2.0f);
  CHECK(frame.label[1] == 7);
  CHECK(frame.part_id[1] == 3);
  CHECK(frame.object_id[1] == 1);
  // A pixel no sample reached keeps the background's values.
  film.resolve(0, PixelSums(), figures);
  CHECK(frame.part_id[0] == -1);
  CHECK(frame.object_id[0] == -1);
  CHECK(frame.sample_count[0] == 0);
}

TEST_CASE("Repeated radiance sums as the same radiance added sample by sample, the second estimate too", "[render]") {
  FrameBuffers frame;
  Film film(frame, 1, 1, AovColorVariance, false, glm::mat3(1.0f));
  PixelSums one_by_one, repeated;
  const glm::vec3 background(0.1f, 0.3f, 0.7f);
  for (int k = 0; k < 37; ++k) film.add_radiance(one_by_one, background, k % 3 == 0);
  film.add_repeated_radiance(repeated, background, 37, true, [](uint32_t k) { return k % 3 == 0; });
  CHECK(std::memcmp(&one_by_one.color, &repeated.color, sizeof(glm::dvec3)) == 0);
  CHECK(std::memcmp(&one_by_one.second_estimate, &repeated.second_estimate, sizeof(glm::dvec3)) == 0);
  CHECK(one_by_one.luminance_squares == repeated.luminance_squares);
  CHECK(one_by_one.samples == repeated.samples);
}

namespace {

// A lit grey floor seen from above, its pixels' evaluation set up as render() sets it up.
struct FloorPixels {
  Scene scene;
  FrameBuffers frame;
  Camera camera = Camera::look_at({0, 0, 2}, {0, 0, 0}, {0, 1, 0}, 0.5, 8, 8);
  RenderSettings settings;

  FloorPixels() {
    scene.add_mesh(test_scenes::horizontal_square(1.0), {scene.add_material(test_scenes::lambert(0.5f))});
    scene.add_lamp(PointLamp{glm::dvec3(0.3, 0.2, 1.0), 5.0, glm::dvec3(1.0)});
    scene.commit();
  }

  // The sums of pixel (x, y) over samples [0, end), taken in runs ending at `ends`.
  PixelSums sums(int x, int y, const std::vector<uint32_t>& ends, bool uniform_background = true) {
    const SceneData& data = scene.data();
    const LightSampler lights = LightSampler::for_scene(data, LightSelection::Importance);
    const CameraRays rays(camera);
    const PathTracer tracer(data, lights, PathSettings(settings, rays.pixel_spread_angle()));
    Film film(frame, camera.width, camera.height, default_aovs(), false, glm::mat3(1.0f));
    RenderControl control(settings, 1u << 20);
    const PixelEvaluator::Setup setup{data,
                                      tracer,
                                      rays,
                                      blackman_harris_sampler(),
                                      camera.width,
                                      1,
                                      pixels_seeing_box(rays, camera.width, camera.height, data.vertex_lower, data.vertex_upper, 1.5),
                                      uniform_background ? lights.uniform_camera_background() : std::nullopt,
                                      true,
                                      nullptr};
    const PixelEvaluator evaluator(setup, film, control);
    PixelSums sums;
    SampleCounts counts;
    RenderControl::Batch progress;
    uint32_t begin = 0;
    for (const uint32_t end : ends) {
      evaluator.take_samples(x, y, begin, end, sums, counts, progress);
      begin = end;
    }
    CHECK(counts.samples == ends.back());
    return sums;
  }
};

bool same_sums(const PixelSums& a, const PixelSums& b) {
  return std::memcmp(&a.color, &b.color, sizeof(glm::dvec3)) == 0 &&
         std::memcmp(&a.second_estimate, &b.second_estimate, sizeof(glm::dvec3)) == 0 &&
         a.luminance_squares == b.luminance_squares && a.coverage == b.coverage && a.samples == b.samples &&
         a.hits == b.hits && a.depth == b.depth && a.label == b.label && a.part == b.part;
}

}  // namespace

TEST_CASE("A pixel's samples in rounds sum as in one run", "[render]") {
  FloorPixels floor;
  const PixelSums whole = floor.sums(4, 4, {48});
  CHECK(whole.hits == 48);
  CHECK(whole.color.x > 0.0);
  CHECK(same_sums(whole, floor.sums(4, 4, {16, 32, 48})));
  CHECK(same_sums(whole, floor.sums(4, 4, {5, 48})));
}

TEST_CASE("A pixel that cannot see the scene sums without rays what its traced samples sum", "[render]") {
  FloorPixels floor;
  floor.scene.set_background(glm::vec3(0.2f, 0.4f, 0.6f));
  floor.camera = Camera::look_at({0, 0, 2}, {0, 0, 0}, {0, 1, 0}, 1.2, 32, 32);  // the corners miss the floor
  const PixelSums without_rays = floor.sums(0, 0, {40});
  const PixelSums traced = floor.sums(0, 0, {40}, /*uniform_background=*/false);
  CHECK(without_rays.hits == 0);
  CHECK(without_rays.color.z > 0.0);
  CHECK(same_sums(without_rays, traced));
}

TEST_CASE("The statistics sum every tile's counts and the occlusion errors' root mean square", "[render]") {
  std::vector<SampleCounts> tiles(3);
  tiles[0].samples = 10;
  tiles[0].rays = 30;
  tiles[1].samples = 5;
  tiles[1].discarded = 2;
  tiles[1].occlusion = {0.02, 0.1, 2};
  tiles[2].occlusion = {0.06, 0.2, 2};
  const RenderStats stats = render_statistics(tiles, 1.5, true);
  CHECK(stats.camera_samples == 15);
  CHECK(stats.rays == 30);
  CHECK(stats.discarded_samples == 2);
  CHECK(stats.occlusion_rms_standard_error == Approx(std::sqrt(0.08 / 4)));
  CHECK(stats.occlusion_max_standard_error == 0.2);
  CHECK(stats.seconds == 1.5);
  CHECK(stats.cancelled);
}

TEST_CASE("The denoiser runs as a post-filter on the finished frame", "[render]") {
  FloorPixels floor;
  RenderSettings settings;
  settings.samples_per_pixel = 8;
  settings.aovs = default_aovs() | kAtrousFilterGuideAovs;
  FrameBuffers raw, filtered;
  render(floor.scene, floor.camera, settings, raw);
  settings.denoise = Denoising::Filter;
  render(floor.scene, floor.camera, settings, filtered);
  atrous_filter(raw);
  CHECK(std::memcmp(raw.color.data(), filtered.color.data(), raw.color.size() * sizeof(float)) == 0);
  CHECK(raw.depth == filtered.depth);
}
