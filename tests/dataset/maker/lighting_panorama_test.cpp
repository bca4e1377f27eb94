// The preview's picture of a frame's lighting (matdataset/maker/lighting_panorama.h): a lamp's
// dot lands where its direction maps in the environment image's own mapping, a rig shows its
// eight lamps, and a uniform world at the frame's exposure is its sRGB value.
#include "matdataset/maker/lighting_panorama.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "matbase/image/srgb.h"

namespace {

using Rgb = std::array<float, 3>;
constexpr int kWidth = 128, kHeight = 64;
const matgeom::Sphere kBounds{glm::dvec3(0.2, -0.1, 0.3), 0.25};

bool is(const Rgb& pixel, const Rgb& colour) {
  return std::abs(pixel[0] - colour[0]) < 1e-6f && std::abs(pixel[1] - colour[1]) < 1e-6f &&
         std::abs(pixel[2] - colour[2]) < 1e-6f;
}

int count(const std::vector<Rgb>& pixels, const Rgb& colour) {
  int n = 0;
  for (const Rgb& pixel : pixels) n += is(pixel, colour);
  return n;
}

}  // namespace

TEST_CASE("A lamp's dot is where the environment image's mapping puts its direction", "[dataset]") {
  // A point lamp straight along +Y of the centre, at the horizon: u = 0.5 - (pi/2) / (2 pi) = 1/4,
  // v = 1/2, so pixel (32, 32); a sun 45 degrees up towards +X: u = 1/2, v = 1 - (pi/4) / pi =
  // 3/4, pixel (64, 16).
  const nlohmann::json lighting = {
      {"lights", {{{"type", "point"}, {"position", {0.2, 1.9, 0.3}}, {"power", 50}},
                  {{"type", "sun"}, {"position", {1, 0, 1}}, {"look_at", {0, 0, 0}}, {"strength", 2}}}},
      {"background", {0.0, 0.0, 0.0}},
      {"exposure_stops", 0.0}};
  const std::vector<Rgb> pixels = matdataset::draw_lighting_panorama(lighting, kBounds, ".", kWidth, kHeight);
  REQUIRE(pixels.size() == static_cast<size_t>(kWidth * kHeight));
  const Rgb white{1.0f, 1.0f, 1.0f}, yellow{1.0f, 0.85f, 0.15f};
  CHECK(is(pixels[32 * kWidth + 32], white));
  CHECK(is(pixels[16 * kWidth + 64], yellow));
  CHECK_FALSE(is(pixels[16 * kWidth + 32], yellow));
  CHECK(count(pixels, white) > 4);
  // Elsewhere the world is black.
  CHECK(is(pixels[48 * kWidth + 96], {0.0f, 0.0f, 0.0f}));
}

TEST_CASE("The rig shows its eight lamps; a uniform world shows its radiance at the frame's exposure", "[dataset]") {
  const nlohmann::json lighting = {{"lights", {{"rig", {{"target_illuminance_lux", 1000}}}}},
                                   {"background", {0.1, 0.2, 0.05}},
                                   {"exposure_stops", 2.0}};
  const std::vector<Rgb> pixels = matdataset::draw_lighting_panorama(lighting, kBounds, ".", kWidth, kHeight);
  const Rgb cyan{0.3f, 0.9f, 1.0f};
  // Each dot is a disc of radius 3.2 pixels: about 32 pixels, eight of them.
  const int lamps = count(pixels, cyan);
  CHECK(lamps > 8 * 20);
  CHECK(lamps < 8 * 45);
  const Rgb world{matbase::linear_to_srgb(0.4f), matbase::linear_to_srgb(0.8f), matbase::linear_to_srgb(0.2f)};
  CHECK(count(pixels, world) > kWidth * kHeight / 2);
}
