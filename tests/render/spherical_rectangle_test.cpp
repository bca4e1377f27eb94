// Solid-angle sampling of rectangles (libmatrender/src/lights/spherical_rectangle): the solid
// angle against the closed form for a rectangle parallel to the xy plane, and the sampled
// directions against per-cell solid angles by chi-square.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "chi_square.h"
#include "uniform_floats.h"
#include "lights/spherical_rectangle.h"

using matrender::Rectangle3;
using matrender::SphericalRectangle;

namespace {

// Solid angle of [x0, x1] x [y0, y1] in the plane at distance h from the origin: inclusion-
// exclusion of F(x, y) = atan(x y / (h sqrt(x^2 + y^2 + h^2))), the solid angle of the
// rectangle between the foot of the perpendicular and corner (x, y) (signed by quadrant).
double closed_form_solid_angle(double x0, double x1, double y0, double y1, double h) {
  const auto f = [h](double x, double y) { return std::atan(x * y / (h * std::sqrt(x * x + y * y + h * h))); };
  return f(x1, y1) - f(x0, y1) - f(x1, y0) + f(x0, y0);
}

// A rectangle posed in a rotated frame, with its coordinates in that frame kept for the closed
// form: the origin sits at height h above the plane of the rectangle.
struct PosedRectangle {
  double x0, x1, y0, y1, h;
  Rectangle3 rect;
  glm::vec3 origin;
};

PosedRectangle pose(double x0, double x1, double y0, double y1, double h) {
  // An arbitrary rotation and translation, so the test exercises the projections too.
  const glm::dvec3 ax = glm::normalize(glm::dvec3(0.6, 0.0, 0.8));
  const glm::dvec3 ay = glm::normalize(glm::cross(glm::dvec3(0.1, 1.0, 0.2), ax));
  const glm::dvec3 az = glm::cross(ax, ay);
  const glm::dvec3 origin(0.3, -0.7, 1.1);
  PosedRectangle p{x0, x1, y0, y1, h, {}, glm::vec3(origin)};
  p.rect.x = glm::vec3(ax);
  p.rect.y = glm::vec3(ay);
  p.rect.z = glm::vec3(az);
  p.rect.length_x = static_cast<float>(x1 - x0);
  p.rect.length_y = static_cast<float>(y1 - y0);
  p.rect.corner = glm::vec3(origin + x0 * ax + y0 * ay - h * az);
  return p;
}

// A test rectangle [x0, x1] x [y0, y1] seen from height h above its plane (see pose()).
struct RectangleCase {
  const char* name;
  double x0, x1, y0, y1, h;
};

}  // namespace

TEST_CASE("The spherical rectangle's solid angle matches the closed form", "[render]") {
  const std::vector<RectangleCase> cases = {
      {"centred square", -0.25, 0.25, -0.25, 0.25, 1.0},
      {"off-axis", 0.4, 1.1, -0.2, 0.5, 0.8},
      {"straddling one axis", -2.0, 3.0, 0.5, 0.9, 0.3},
      {"large and close (near 2 pi)", -10.0, 10.0, -10.0, 10.0, 0.01},
      {"tiny, straight ahead", -5e-4, 5e-4, -5e-4, 5e-4, 1.0},
      {"tiny, off-axis", 2.0, 2.001, 1.0, 1.002, 1.0},
      {"grazing", 1.0, 2.0, -0.5, 0.5, 1e-3},
  };
  for (const RectangleCase& c : cases) {
    const PosedRectangle p = pose(c.x0, c.x1, c.y0, c.y1, c.h);
    const double expected = closed_form_solid_angle(c.x0, c.x1, c.y0, c.y1, c.h);
    const float got = SphericalRectangle(p.origin, p.rect).solid_angle();
    // Single precision: the posed coordinates carry about 1e-7 relative error, and the four
    // corner terms (each up to pi/2) about 1e-7 absolute, which a rectangle far off-axis cancels
    // down to its solid angle. (Lamps switch to area sampling below 1e-3 sr.)
    INFO(c.name << ": expected " << expected << ", got " << got);
    CHECK(got == Approx(expected).epsilon(2e-4).margin(1e-7));
  }
}

TEST_CASE("Spherical rectangle samples are uniform in solid angle (chi-square)", "[render]") {
  const std::vector<RectangleCase> cases = {
      {"centred square", -0.25, 0.25, -0.25, 0.25, 1.0},
      {"off-axis, close", 0.1, 1.5, -0.3, 0.9, 0.2},
      {"wide, grazing", 0.2, 4.0, -1.0, 1.0, 0.05},
  };
  constexpr int kCells = 8;  // per side
  constexpr int kSamples = 200000;
  // Bonferroni over the cases for a family-wise false-failure rate of 1e-3.
  const double significance = 1e-3 / static_cast<double>(cases.size());
  UniformFloats rng(0x5eed0003);
  for (const RectangleCase& c : cases) {
    const PosedRectangle p = pose(c.x0, c.x1, c.y0, c.y1, c.h);
    const SphericalRectangle spherical(p.origin, p.rect);
    const double total = closed_form_solid_angle(c.x0, c.x1, c.y0, c.y1, c.h);
    std::vector<int> counts(kCells * kCells, 0);
    const double wx = (c.x1 - c.x0) / kCells, wy = (c.y1 - c.y0) / kCells;
    for (int i = 0; i < kSamples; ++i) {
      const glm::vec3 point = spherical.sample(rng.next2());
      const glm::dvec3 local = glm::dvec3(point) - glm::dvec3(p.rect.corner);
      const double lx = glm::dot(local, glm::dvec3(p.rect.x)), ly = glm::dot(local, glm::dvec3(p.rect.y));
      REQUIRE(std::abs(glm::dot(local, glm::dvec3(p.rect.z))) < 1e-5);
      REQUIRE(lx >= -1e-5);
      REQUIRE(ly >= -1e-5);
      REQUIRE(lx <= p.rect.length_x + 1e-5);
      REQUIRE(ly <= p.rect.length_y + 1e-5);
      const int cx = std::min(kCells - 1, std::max(0, static_cast<int>(lx / wx)));
      const int cy = std::min(kCells - 1, std::max(0, static_cast<int>(ly / wy)));
      ++counts[cy * kCells + cx];
    }
    double statistic = 0.0;
    for (int cy = 0; cy < kCells; ++cy)
      for (int cx = 0; cx < kCells; ++cx) {
        const double cell = closed_form_solid_angle(c.x0 + cx * wx, c.x0 + (cx + 1) * wx, c.y0 + cy * wy,
                                                    c.y0 + (cy + 1) * wy, c.h);
        const double expected = kSamples * cell / total;
        const double d = counts[cy * kCells + cx] - expected;
        statistic += d * d / expected;
      }
    const double p_value = chi_square_survival(statistic, kCells * kCells - 1);
    INFO(c.name << ": chi^2 = " << statistic << ", p = " << p_value);
    CHECK(p_value > significance);
  }
}

TEST_CASE("Spherical rectangle samples at v = 0 and v -> 1 land on the near and far y edges", "[render]") {
  // The second variable moves the point from the y0 edge to the y1 edge. Rectangles reaching far
  // along -y or +y put |h0| or |h1| within float rounding of 1, where the y coordinate must come
  // from the edge on that side.
  const std::vector<RectangleCase> cases = {
      {"ordinary", -0.4, 0.3, -0.2, 0.6, 1.0},
      {"far along -y", -0.4, 0.3, -1e4, 0.5, 1.0},
      {"far along +y", -0.4, 0.3, -0.5, 1e4, 1.0},
  };
  for (const RectangleCase& c : cases) {
    const PosedRectangle p = pose(c.x0, c.x1, c.y0, c.y1, c.h);
    const SphericalRectangle spherical(p.origin, p.rect);
    for (float u : {0.1f, 0.5f, 0.9f}) {
      const auto local_y = [&](float v) {
        const glm::dvec3 local = glm::dvec3(spherical.sample({u, v})) - glm::dvec3(p.rect.corner);
        return glm::dot(local, glm::dvec3(p.rect.y));
      };
      INFO(c.name << ", u = " << u);
      CHECK(local_y(0.0f) == Approx(0.0).margin(1e-3 * p.rect.length_y));
      CHECK(local_y(0x1.fffffep-1f) == Approx(p.rect.length_y).margin(1e-3 * p.rect.length_y));
    }
  }
}
