// Mip-mapped texture filtering by ray cones: a checkerboard of one-texel squares on a plane seen
// at grazing angles. Far away each pixel covers hundreds of checks: without mip levels every
// sample lands on a 0 or a 1 and pixels are noise around the mean 0.5; with them each sample
// already reads the box-filtered mean. Both converge to the same pixels; the texture's own levels
// are 2 x 2 box filters (every level above the finest averages the checks to exactly 0.5).
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "matrender/camera.h"
#include "matrender/render.h"
#include "matrender/scene.h"
#include "matrender/texture.h"
#include "test_scenes.h"

using namespace matrender;

namespace {

TexturePtr checkerboard(int side) {
  std::vector<float> pixels;
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) pixels.push_back(static_cast<float>((x + y) % 2));
  return Texture::from_pixelsf(side, side, 1, pixels.data(), ColorSpace::NonColor);
}

// The checkerboard as the emission of a black plane 40 m across with UVs repeated 400 times, seen
// from 0.3 m above at a grazing angle: the camera sees the emission alone, no lighting noise.
std::vector<float> render_checkerboard(bool mipmaps, int spp, uint32_t seed) {
  Scene scene;
  matgeom::TriangleMesh plane = test_scenes::horizontal_square(40.0);
  for (glm::vec2& uv : plane.uvs) uv *= 400.0f;
  Material m = test_scenes::lambert(0.0f);
  m[MaterialParameter::Emission].value = glm::vec3(1.0f);
  m[MaterialParameter::Emission].texture = checkerboard(64);
  scene.add_mesh(plane, {scene.add_material(m)});
  RenderSettings settings;
  settings.samples_per_pixel = spp;
  settings.seed = seed;
  settings.mipmaps = mipmaps;
  settings.aovs = 0;
  FrameBuffers frame;
  const Camera camera = Camera::look_at({0.0, 0.0, 0.3}, {0.0, 8.0, 0.0}, {0, 0, 1}, 0.6, 48, 48);
  REQUIRE(render(scene, camera, settings, frame).discarded_samples == 0);
  std::vector<float> green;
  for (size_t i = 1; i < frame.color.size(); i += 3) green.push_back(frame.color[i]);
  return green;
}

double mean_squared_difference(const std::vector<float>& a, const std::vector<float>& b, size_t first) {
  double sum = 0.0;
  for (size_t i = first; i < a.size(); ++i) sum += (double(a[i]) - b[i]) * (double(a[i]) - b[i]);
  return sum / static_cast<double>(a.size() - first);
}

}  // namespace

TEST_CASE("Mip-mapping a grazing checkerboard converges to the same pixels with far less noise", "[render]") {
  const std::vector<float> reference = render_checkerboard(false, 1024, 9);
  // The image's top half: the plane toward the horizon, where a pixel covers many checks, and the
  // black sky above it.
  const size_t horizon_rows_end = 48 * 24;
  const std::vector<float> plain_a = render_checkerboard(false, 4, 1), plain_b = render_checkerboard(false, 4, 2);
  const std::vector<float> mip_a = render_checkerboard(true, 4, 1), mip_b = render_checkerboard(true, 4, 2);
  // Variance at 4 spp, from two independent renders: E[(a - b)^2] = 2 var.
  const double plain_variance = 0.5 * mean_squared_difference(plain_a, plain_b, 0);
  const double mip_variance = 0.5 * mean_squared_difference(mip_a, mip_b, 0);
  // The error of mip-mapped renders against the converged plain one: noise plus the filter's bias.
  const std::vector<float> mip_converged = render_checkerboard(true, 256, 3);
  const double bias2 = mean_squared_difference(mip_converged, reference, 0);
  double reference_mean = 0.0, mip_mean = 0.0;
  for (size_t i = 0; i < horizon_rows_end; ++i) reference_mean += reference[i], mip_mean += mip_converged[i];
  INFO("variance at 4 spp: plain " << plain_variance << ", mip-mapped " << mip_variance
                                   << "; mean squared difference of the converged images " << bias2
                                   << "; mean of the top half " << reference_mean / horizon_rows_end << " against "
                                   << mip_mean / horizon_rows_end);
  CHECK(mip_variance < plain_variance / 10.0);
  // The box filter widens each pixel's footprint a little: its error is far below the noise it saves.
  CHECK(bias2 < plain_variance / 10.0);
  CHECK(std::abs(reference_mean - mip_mean) / horizon_rows_end < 0.01);
}

TEST_CASE("Mip levels are 2 x 2 box filters down to one texel, used only where a footprint asks", "[render]") {
  const TexturePtr checks = checkerboard(8);
  // Magnified or one texel wide: the bilinear lookup itself (the top row, v near 1, starts with 0).
  CHECK(checks->sample({0.5f / 8.0f, 7.5f / 8.0f}, false, 0.0f).x == 0.0f);
  CHECK(checks->sample({1.5f / 8.0f, 7.5f / 8.0f}, false, 1.0f / 8.0f).x == 1.0f);
  // Two texels wide: level 1, where every texel averages two checks of each colour.
  CHECK(checks->sample({0.3f, 0.7f}, false, 2.0f / 8.0f).x == Approx(0.5f));
  // Far wider than the texture: its 1 x 1 level.
  CHECK(checks->sample({0.3f, 0.7f}, false, 100.0f).x == Approx(0.5f));
  // Between levels 0 and 1 the lookup blends them: at sqrt(2) texels, halfway in log2.
  const float blended = checks->sample({1.5f / 8.0f, 7.5f / 8.0f}, false, std::sqrt(2.0f) / 8.0f).x;
  CHECK(blended == Approx(0.5f * 1.0f + 0.5f * 0.5f));
}
