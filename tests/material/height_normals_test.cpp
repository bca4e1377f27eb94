// The normal map of a height field and the value noise both kinds of procedural texture share,
// held to closed forms: a sine relief's slope, a plane's normal, and value noise's bounds,
// periodicity and corner values.
#include <cmath>
#include <cstdint>
#include <vector>

#include <catch2/catch.hpp>
#include <glm/glm.hpp>

#include "matbase/pi.h"
#include "matmaterial/library/height_normals.h"
#include "matmaterial/library/periodic_noise.h"

namespace {

using matmaterial::library::ValueNoiseBlend;

// A byte as unorm8 writes it, for the closed form's normal component n in [-1, 1].
double byte_of(double n) { return std::round((0.5 * n + 0.5) * 255.0); }

}  // namespace

TEST_CASE("A height field's normal map tilts against the slope, wrapping at the edges", "[material]") {
  constexpr int kSize = 32;
  constexpr double kAmplitude = 0.3, kTexel = 0.5;
  // h = A sin(2 pi x / N) along u: the central difference is exactly
  // A cos(2 pi x / N) sin(2 pi / N) / texel (a sum-to-product identity), the same at the wrap.
  std::vector<double> heights(kSize * kSize);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) heights[y * kSize + x] = kAmplitude * std::sin(2.0 * matbase::kPi * x / kSize);
  std::vector<uint8_t> row(3 * kSize);
  for (int y : {0, 7, kSize - 1}) {
    matmaterial::library::normal_map_row(heights, kSize, kTexel, y, row.data());
    for (int x = 0; x < kSize; ++x) {
      const double slope =
          kAmplitude * std::cos(2.0 * matbase::kPi * x / kSize) * std::sin(2.0 * matbase::kPi / kSize) / kTexel;
      const glm::dvec3 n = glm::normalize(glm::dvec3(-slope, 0.0, 1.0));
      CAPTURE(x, y);
      CHECK(std::abs(row[3 * x] - byte_of(n.x)) <= 1.0);
      CHECK(row[3 * x + 1] == 128);  // flat along v: 0.5 rounds to 128
      CHECK(std::abs(row[3 * x + 2] - byte_of(n.z)) <= 1.0);
    }
  }
  // Rising towards the top of the image (+v, up the rows) tilts the normal towards -v.
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) heights[y * kSize + x] = kAmplitude * std::sin(2.0 * matbase::kPi * -y / kSize);
  matmaterial::library::normal_map_row(heights, kSize, kTexel, 0, row.data());
  CHECK(row[0] == 128);
  CHECK(row[1] < 128);
}

TEST_CASE("Value noise of either blend stays in [0, 1], tiles, and takes its lattice values at the corners",
          "[material]") {
  for (const ValueNoiseBlend blend : {ValueNoiseBlend::Quintic, ValueNoiseBlend::CubicOnceHashed}) {
    const glm::ivec2 period(5, 3);
    for (int k = 0; k < 500; ++k) {
      const glm::dvec2 uv(k * 0.0137, k * 0.0291);
      const double n = matmaterial::library::value_noise(uv, period, 11u, blend);
      CHECK(n >= 0.0);
      CHECK(n <= 1.0);
      // One tile over, in either direction, is the same noise.
      CHECK(matmaterial::library::value_noise(uv + glm::dvec2(1.0, 0.0), period, 11u, blend) == Approx(n).margin(1e-12));
      CHECK(matmaterial::library::value_noise(uv + glm::dvec2(0.0, -1.0), period, 11u, blend) == Approx(n).margin(1e-12));
    }
  }
  // At a lattice point the fade is 0 or 1: the library's noise takes that corner's hashed value.
  const double corner = matmaterial::library::value_noise({2.0 / 5.0, 1.0 / 3.0}, {5, 3}, 11u);
  CHECK(corner == Approx(matmaterial::library::hash_to_unit(matmaterial::library::lattice_hash(2, 1, {5, 3}, 11u)))
                      .margin(1e-12));
  // The two blends are different noises: the built-in vase keeps the one it was drawn with.
  CHECK(matmaterial::library::value_noise({0.31, 0.77}, {5, 3}, 11u, ValueNoiseBlend::Quintic) !=
        matmaterial::library::value_noise({0.31, 0.77}, {5, 3}, 11u, ValueNoiseBlend::CubicOnceHashed));
}
