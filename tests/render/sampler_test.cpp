// The per-pixel sampler: each dimension pair is a scrambled (0,2)-sequence, so every power-of-two
// prefix is stratified in every elementary interval; pairs and pixels are decorrelated.
#include <catch2/catch.hpp>

#include <set>
#include <vector>

#include "film/pixel_filter.h"
#include "matrender/render.h"
#include "matrender/scene.h"
#include "sampling/pixel_sampler.h"
#include "sampling/sample_packet.h"
#include "test_scenes.h"

using namespace matrender;

TEST_CASE("Each pair's first 2^m points form a (0,m,2)-net", "[render]") {
  for (uint32_t pixel : {0u, 17u, 123456u}) {
    const PixelSeeds seeds(pixel, 42);
    for (uint32_t pair : {0u, 1u, 5u, 70u}) {  // 70: beyond the cached pairs
      const int m = 8;
      const uint32_t n = 1u << m;
      std::vector<glm::vec2> points;
      for (uint32_t i = 0; i < n; ++i) points.push_back(PixelSampler(seeds, i).get_2d(pair));
      // Every elementary interval of shape 2^-a x 2^-(m-a) holds exactly one point.
      for (int a = 0; a <= m; ++a) {
        std::set<std::pair<uint32_t, uint32_t>> cells;
        for (const glm::vec2& p : points) {
          REQUIRE(p.x >= 0.0f);
          REQUIRE(p.x < 1.0f);
          REQUIRE(p.y >= 0.0f);
          REQUIRE(p.y < 1.0f);
          cells.insert({static_cast<uint32_t>(p.x * float(1u << a)), static_cast<uint32_t>(p.y * float(1u << (m - a)))});
        }
        INFO("pixel " << pixel << " pair " << pair << " interval 2^-" << a << " x 2^-" << (m - a));
        CHECK(cells.size() == n);
      }
    }
  }
}

TEST_CASE("Different pixels, pairs and seeds give different points", "[render]") {
  const PixelSeeds a(3, 0), b(4, 0), c(3, 1);
  CHECK(PixelSampler(a, 0).get_2d(1) != PixelSampler(b, 0).get_2d(1));
  CHECK(PixelSampler(a, 0).get_2d(1) != PixelSampler(a, 0).get_2d(2));
  CHECK(PixelSampler(a, 0).get_2d(1) != PixelSampler(c, 0).get_2d(1));
  // Same inputs, same point: the image cannot depend on evaluation order.
  const PixelSeeds a_again(3, 0);
  CHECK(PixelSampler(a, 9).get_2d(7) == PixelSampler(a_again, 9).get_2d(7));
}

TEST_CASE("A sample packet holds the scalar sampler's points, bit for bit, on every instruction set", "[render]") {
  // Packets start anywhere (render.cpp steps by kPacketSamples), including where the index
  // wraps past 2^32.
  const std::vector<LaneIsa> isas = supported_lane_isas();
  REQUIRE(isas.front() == LaneIsa::Baseline);
  for (uint32_t pixel : {0u, 17u, 123456u}) {
    for (uint32_t seed : {0u, 42u}) {
      const PixelSeeds seeds(pixel, seed);
      for (uint32_t first : {0u, 16u, 1000u, 0xFFFFFFF8u}) {
        for (LaneIsa isa : isas) {
          const SamplePacket packet(seeds, first, isa);
          for (int lane = 0; lane < kPacketSamples; ++lane) {
            const PixelSampler scalar(seeds, first + static_cast<uint32_t>(lane));
            const PixelSampler from_packet(packet, lane);
            for (uint32_t pair = 0; pair < kPacketPairs + 2; ++pair) {
              INFO("pixel " << pixel << " seed " << seed << " sample " << first + lane << " pair " << pair
                            << " instruction set " << static_cast<int>(isa));
              REQUIRE(from_packet.get_2d(pair) == scalar.get_2d(pair));
              if (pair < kPacketPairs) REQUIRE(packet.point(pair, lane) == scalar.get_2d(pair));
            }
          }
        }
        // The default constructor picks one of them: same points again.
        const SamplePacket widest(seeds, first);
        for (int lane = 0; lane < kPacketSamples; ++lane)
          REQUIRE(widest.point(1, lane) == PixelSampler(seeds, first + static_cast<uint32_t>(lane)).get_2d(1));
      }
    }
  }
}

TEST_CASE("The pixel filter's inverse CDF follows Blackman-Harris", "[render]") {
  const PixelFilterSampler& filter = blackman_harris_sampler();
  CHECK(filter.inverse_cdf(0.0f) == Approx(-1.5f));
  CHECK(filter.inverse_cdf(0.5f) == Approx(0.0f).margin(1e-6));
  CHECK(filter.inverse_cdf(1.0f) == Approx(1.5f));
  // The fraction of mass within |x| < 0.5 px, by Simpson integration of the window itself.
  double inside = 0.0, total = 0.0;
  const int steps = 3000;
  for (int i = 0; i <= steps; ++i) {
    const double x = -1.5 + 3.0 * i / steps;
    const double w = blackman_harris_weight(x, 1.5) * ((i == 0 || i == steps) ? 1 : (i % 2 ? 4 : 2));
    total += w;
    if (std::abs(x) < 0.5) inside += w;
  }
  int hits = 0;
  const int n = 100000;
  for (int i = 0; i < n; ++i)
    if (std::abs(filter.inverse_cdf((i + 0.5f) / n)) < 0.5f) ++hits;
  CHECK(double(hits) / n == Approx(inside / total).margin(2e-3));
}

TEST_CASE("Sobol dimension 1 equals the direction-number recurrence", "[render]") {
  // The textbook construction: XOR of direction numbers v_k for the set bits k of the index,
  // v_0 = 2^31, v_k = v_{k-1} ^ (v_{k-1} >> 1) (Pascal's triangle mod 2).
  const auto by_direction_numbers = [](uint32_t index) {
    uint32_t result = 0, direction = 0x80000000u;
    for (; index != 0; index >>= 1, direction ^= direction >> 1)
      if (index & 1u) result ^= direction;
    return result;
  };
  uint32_t index = 0;
  for (int i = 0; i < 100000; ++i, index = hash_u32(index + 1)) {
    INFO("index " << index);
    REQUIRE(sobol_dimension1(index) == by_direction_numbers(index));
    REQUIRE(reverse_bits(reverse_bits(index)) == index);
    const uint32_t other = hash_u32(index);
    REQUIRE(reverse_bits64((uint64_t{other} << 32) | index) ==
            ((uint64_t{reverse_bits(index)} << 32) | reverse_bits(other)));
  }
  for (uint32_t small = 0; small < 4096; ++small) REQUIRE(sobol_dimension1(small) == by_direction_numbers(small));
  CHECK(reverse_bits(1u) == 0x80000000u);
  CHECK(reverse_bits(0x00000F01u) == 0x80F00000u);
}

TEST_CASE("A pixel filter of another width is Blender's default one scaled", "[render]") {
  // Blackman-Harris over [-r, r] is the window over [-1.5, 1.5] stretched by r / 1.5, and so is
  // its inverse CDF; the default width's filter is the one made once.
  const PixelFilterSampler& standard = blackman_harris_sampler();
  CHECK(standard.radius() == 1.5);
  for (const double radius : {0.01, 0.5, 4.0, 10.0}) {
    const PixelFilterSampler filter(radius);
    CHECK(filter.radius() == radius);
    CHECK(filter.inverse_cdf(0.0f) == Approx(-radius));
    CHECK(filter.inverse_cdf(1.0f) == Approx(radius));
    for (int i = 0; i <= 64; ++i) {
      const float u = i / 64.0f;
      CHECK(filter.inverse_cdf(u) == Approx(standard.inverse_cdf(u) * radius / 1.5).margin(1e-5 * radius));
    }
  }
  const PixelFilterSampler again(PixelFilterSampler::kDefaultRadius);
  for (int i = 0; i <= 64; ++i) CHECK(again.inverse_cdf(i / 64.0f) == standard.inverse_cdf(i / 64.0f));
}

TEST_CASE("A wider pixel filter spreads an edge over more pixels", "[render]") {
  // A white floor's straight edge against a black background, seen from above: the row's
  // values rise from 0 to 1 over the pixels within the filter's reach of the edge.
  Scene scene;
  Material white = test_scenes::lambert(0.0f);
  white.set(MaterialParameter::Emission, glm::vec3(1.0f));
  white.set(MaterialParameter::EmissionStrength, 1.0f);
  scene.add_mesh(test_scenes::horizontal_square(1.0), {scene.add_material(white)});
  const Camera camera = Camera::look_at({0.5, 0, 2}, {0.5, 0, 0}, {0, 1, 0}, 0.4, 48, 4);  // the edge at x = 0.5
  auto ramp_pixels = [&](double width) {
    RenderSettings settings;
    settings.samples_per_pixel = 256;
    settings.filter_width = width;
    settings.aovs = 0;
    FrameBuffers frame;
    render(scene, camera, settings, frame);
    int partial = 0;
    for (int x = 0; x < camera.width; ++x) {
      const float v = frame.color[3 * (2 * camera.width + x)];
      if (v > 0.02f && v < 0.98f) ++partial;
    }
    return partial;
  };
  const int narrow = ramp_pixels(0.5), standard = ramp_pixels(1.5), wide = ramp_pixels(4.0);
  CAPTURE(narrow, standard, wide);
  CHECK(narrow <= 2);
  CHECK(standard > narrow);
  CHECK(wide >= 2 * standard);
  CHECK(wide <= 8 + 2);  // the window's reach either side, and a pixel of rounding
}

