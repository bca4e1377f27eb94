// The ambient-occlusion AOV against its closed form, and the tangent-space normal AOV against
// the normal map's texel.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>

#include "matrender/camera.h"
#include "matrender/render.h"
#include "matrender/scene.h"
#include "test_scenes.h"

using namespace matrender;

namespace {

// A floor at z = 0 and, when ceiling_height > 0, a ceiling above it, both 400 m wide so that their
// edges lie far beyond any occlusion distance used here; the camera looks straight down at the
// floor from below the ceiling.
FrameBuffers render_floor(double ceiling_height, double distance, int spp, int rays, uint32_t aovs,
                          double error = 0.0, RenderStats* stats = nullptr) {
  Scene scene;
  const uint32_t grey = scene.add_material(test_scenes::lambert(0.5f));
  scene.add_mesh(test_scenes::horizontal_square(400.0), {grey});
  if (ceiling_height > 0.0) scene.add_mesh(test_scenes::horizontal_square(400.0, ceiling_height), {grey});
  scene.add_lamp(PointLamp{glm::dvec3(0.0, 0.0, 0.1), 1.0, glm::dvec3(1.0)});
  const Camera camera = Camera::look_at({0, 0, 0.1}, {0, 0, 0}, {0, 1, 0}, 0.5, 24, 24);
  RenderSettings settings;
  settings.samples_per_pixel = spp;
  settings.ambient_occlusion_rays = rays;
  settings.ambient_occlusion_distance = distance;
  settings.ambient_occlusion_error = error;
  settings.aovs = aovs;
  settings.seed = 11;
  FrameBuffers frame;
  const RenderStats result = render(scene, camera, settings, frame);
  if (stats) *stats = result;
  return frame;
}

// Root mean square of a - b over the pixels where `mask` > 0.
double rms_difference(const std::vector<float>& a, const std::vector<float>& b, const std::vector<float>& mask) {
  double sum = 0.0;
  size_t n = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    if (!(mask[i] > 0.0f)) continue;
    sum += (double(a[i]) - b[i]) * (double(a[i]) - b[i]);
    ++n;
  }
  return n > 0 ? std::sqrt(sum / static_cast<double>(n)) : 0.0;
}

}  // namespace

TEST_CASE("Ambient occlusion under a parallel plane is (h / d)^2", "[render]") {
  // A cosine-distributed direction at angle theta from the floor's normal meets the ceiling at
  // distance h / cos theta, within d when cos theta > h / d; P(cos theta > c) = 1 - c^2 for the
  // cosine distribution, so the unoccluded fraction is (h / d)^2.
  constexpr int kSpp = 16, kRays = 4;
  for (const double h : {0.3, 0.5, 0.8}) {
    const double distance = 1.0;
    const double expected = (h / distance) * (h / distance);
    const FrameBuffers frame = render_floor(h, distance, kSpp, kRays, AovAmbientOcclusion);
    // Every pixel's estimate averages spp x rays Bernoulli trials; stratification only lowers the
    // variance, so the independent-trial standard error bounds the mean's.
    const double trials = static_cast<double>(frame.ambient_occlusion.size()) * kSpp * kRays;
    const double standard_error = std::sqrt(expected * (1.0 - expected) / trials);
    CAPTURE(h, standard_error);
    CHECK(test_scenes::mean_of(frame.ambient_occlusion) == Approx(expected).margin(4.0 * standard_error));
    for (const float ao : frame.ambient_occlusion) REQUIRE((ao >= 0.0f && ao <= 1.0f));
  }
}

TEST_CASE("Nothing within the occlusion distance leaves ambient occlusion at exactly 1", "[render]") {
  // The ceiling at 0.5 m lies beyond a distance of 0.4 m in every direction; the open floor
  // meets nothing at all.
  for (const double h : {0.5, 0.0}) {
    const FrameBuffers frame = render_floor(h, 0.4, 4, 2, AovAmbientOcclusion);
    for (const float ao : frame.ambient_occlusion) REQUIRE(ao == 1.0f);
  }
}

TEST_CASE("Asking for ambient occlusion leaves the colour as it was", "[render]") {
  // Its directions use their own random sequence, not the path's.
  const FrameBuffers with = render_floor(0.5, 1.0, 8, 2, AovAmbientOcclusion | AovAlpha);
  const FrameBuffers without = render_floor(0.5, 1.0, 8, 2, AovAlpha);
  CHECK(with.color == without.color);
  CHECK(without.ambient_occlusion.empty());
}

TEST_CASE("The tangent-space normal AOV is the normal map's texel, (0, 0, 1) without one", "[render]") {
  matgeom::TriangleMesh plane = test_scenes::horizontal_square(2.0);
  plane.normals.assign(4, glm::vec3(0, 0, 1));
  plane.tangents.assign(4, glm::vec4(1, 0, 0, 1));
  plane.triangle_parts = {0, 1};
  Material flat = test_scenes::lambert(0.5f), bumpy = test_scenes::lambert(0.5f);
  const std::array<float, 3> texel = {0.75f, 0.4f, 0.9f};
  bumpy.normal_map = Texture::from_pixelsf(1, 1, 3, texel.data(), ColorSpace::NonColor);
  Scene scene;
  scene.add_mesh(plane, {scene.add_material(flat), scene.add_material(bumpy)});
  scene.add_lamp(PointLamp{glm::dvec3(0, 0, 1), 10.0, glm::dvec3(1.0)});
  RenderSettings settings;
  settings.samples_per_pixel = 4;
  settings.aovs = AovNormalTangent | AovPartId;
  FrameBuffers frame;
  render(scene, Camera::look_at({0, 0, 2}, {0, 0, 0}, {0, 1, 0}, 0.8, 16, 16), settings, frame);

  const glm::vec3 expected = glm::normalize(2.0f * glm::vec3(texel[0], texel[1], texel[2]) - glm::vec3(1.0f));
  int flat_pixels = 0, bumpy_pixels = 0;
  for (size_t i = 0; i < frame.part_id.size(); ++i) {
    const glm::vec3 n(frame.normal_tangent[3 * i], frame.normal_tangent[3 * i + 1], frame.normal_tangent[3 * i + 2]);
    // Pixels on the diagonal seam mix both parts.
    const bool seam = std::abs(static_cast<int>(i % 16) - static_cast<int>(15 - i / 16)) <= 1;
    if (seam) continue;
    const glm::vec3 want = frame.part_id[i] == 1 ? expected : glm::vec3(0, 0, 1);
    (frame.part_id[i] == 1 ? bumpy_pixels : flat_pixels)++;
    for (int c = 0; c < 3; ++c) CHECK(n[c] == Approx(want[c]).margin(1e-5));
  }
  CHECK(flat_pixels > 50);
  CHECK(bumpy_pixels > 50);
}

TEST_CASE("Ambient occlusion to an error bound stays within it at a fraction of the worst case's rays", "[render]") {
  // Under a plane at h the unoccluded fraction is (h / d)^2 at every pixel: every pixel's error is
  // its own, and their RMS must stay within the bound. An open floor (nothing within d) needs far
  // fewer rays than the worst case 0.25 / error^2 per pixel, a half-occluded one about that many.
  constexpr int kSpp = 16;
  constexpr double kError = 0.02;
  const double worst_case_trials = 0.25 / (kError * kError);
  for (const double h : {0.0, 0.3, std::sqrt(0.5), 0.95}) {
    const double expected = h > 0.0 ? h * h : 1.0;
    RenderStats stats;
    const FrameBuffers frame = render_floor(h, 1.0, kSpp, 1, AovAmbientOcclusion | AovAlpha, kError, &stats);
    const std::vector<float> truth(frame.ambient_occlusion.size(), static_cast<float>(expected));
    const double rms = rms_difference(frame.ambient_occlusion, truth, frame.alpha);
    // Rays per pixel: the occlusion rays beside the camera samples' own (at most 2 each here: a
    // lamp and a bounce ray, counted in both renders alike).
    RenderStats fixed_stats;
    render_floor(h, 1.0, kSpp, 1, AovAmbientOcclusion, 0.0, &fixed_stats);
    const double pixels = static_cast<double>(frame.alpha.size());
    const double occlusion_rays = (static_cast<double>(stats.rays) - (static_cast<double>(fixed_stats.rays) - kSpp * pixels)) / pixels;
    CAPTURE(h, rms, occlusion_rays, stats.occlusion_rms_standard_error, stats.occlusion_max_standard_error);
    CHECK(rms <= kError);
    CHECK(stats.occlusion_rms_standard_error <= kError);
    CHECK(stats.occlusion_max_standard_error <= kError);
    if (h == 0.0) CHECK(occlusion_rays < 0.25 * worst_case_trials);
    CHECK(occlusion_rays < 1.3 * worst_case_trials);
  }
}

TEST_CASE("Ambient occlusion to an error bound agrees with a high-ray reference where occlusion varies", "[render]") {
  // A ball resting on a floor: occlusion from none far away to nearly full at the contact.
  Scene scene;
  const uint32_t grey = scene.add_material(test_scenes::lambert(0.5f));
  scene.add_mesh(test_scenes::horizontal_square(400.0), {grey});
  scene.add_mesh(test_scenes::uv_sphere(0.3, 24, {0.0, 0.0, 0.3}), {grey});
  scene.add_lamp(PointLamp{glm::dvec3(1.0, -1.0, 2.0), 50.0, glm::dvec3(1.0)});
  const Camera camera = Camera::look_at({1.2, -1.2, 0.9}, {0, 0, 0.15}, {0, 0, 1}, 0.8, 40, 30);
  RenderSettings settings;
  settings.aovs = AovAmbientOcclusion | AovAlpha;
  settings.samples_per_pixel = 256;
  settings.ambient_occlusion_rays = 64;  // 16,384 trials a pixel: standard error below 0.004
  settings.seed = 5;
  FrameBuffers reference, bounded;
  render(scene, camera, settings, reference);
  constexpr double kError = 0.02;
  settings.samples_per_pixel = 32;
  settings.ambient_occlusion_error = kError;
  settings.seed = 6;
  const RenderStats stats = render(scene, camera, settings, bounded);
  const double rms = rms_difference(bounded.ambient_occlusion, reference.ambient_occlusion, reference.alpha);
  CAPTURE(rms, stats.occlusion_rms_standard_error);
  // The reference's own noise adds in quadrature.
  CHECK(rms <= std::sqrt(kError * kError + 0.004 * 0.004));
  CHECK(stats.occlusion_rms_standard_error <= kError);
}

TEST_CASE("Ambient occlusion without rays or with a distance of 0 is refused", "[render]") {
  // In the words of the settings' declarations (matrender/render_setting_declarations.h).
  CHECK_THROWS_WITH(render_floor(0.5, 1.0, 1, 0, AovAmbientOcclusion),
                    "render: ambient_occlusion_rays: expected a whole number from 1 to 1,024, got 0");
  CHECK_THROWS_WITH(render_floor(0.5, 0.0, 1, 1, AovAmbientOcclusion),
                    "render: ambient_occlusion_distance: expected a number greater than 0 and at most 65536, got 0");
  CHECK_THROWS_WITH(render_floor(0.5, 1.0, 1, 1, AovAmbientOcclusion, 0.0001),
                    "render: ambient_occlusion_error: expected 0 (a fixed ray count: `ambient_occlusion_rays` per "
                    "hit) or a number from 0.001 to 0.5, got 0.0001");
  CHECK_THROWS_WITH(render_floor(0.5, 1.0, 1, 1, AovAmbientOcclusion, std::nan("")),
                    Catch::StartsWith("render: ambient_occlusion_error: expected 0") && Catch::EndsWith("got nan"));
  // A setting out of range is refused whether or not this render uses it, as a scene file would.
  CHECK_THROWS_WITH(render_floor(0.5, 0.0, 1, 1, AovAlpha), Catch::StartsWith("render: ambient_occlusion_distance"));
}
