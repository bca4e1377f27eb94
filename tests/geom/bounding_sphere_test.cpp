#include "matgeom/bounding_sphere.h"

#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <vector>

#include "matbase/pi.h"

namespace {

using matgeom::Sphere;

double max_distance(const std::vector<glm::dvec3>& points, const glm::dvec3& center) {
  double largest = 0.0;
  for (const glm::dvec3& p : points) largest = std::max(largest, glm::distance(p, center));
  return largest;
}

// The sphere through the subset's points with its centre in their affine hull, from the
// linear system 2 e_k . x = |e_k|^2 (e_k = p_k - p_0, x = centre - p_0, x in span{e_k}).
std::optional<Sphere> circumsphere_in_affine_hull(const std::vector<glm::dvec3>& subset) {
  const glm::dvec3 a = subset[0];
  if (subset.size() == 1) return Sphere{a, 0.0};
  if (subset.size() == 2) return Sphere{0.5 * (a + subset[1]), 0.5 * glm::distance(a, subset[1])};
  if (subset.size() == 3) {
    // x = s e1 + t e2; Gram system [e1.e1 e1.e2; e1.e2 e2.e2] (s, t) = (|e1|^2, |e2|^2) / 2.
    const glm::dvec3 e1 = subset[1] - a, e2 = subset[2] - a;
    const double g11 = glm::dot(e1, e1), g12 = glm::dot(e1, e2), g22 = glm::dot(e2, e2);
    const double det = g11 * g22 - g12 * g12;
    if (std::abs(det) <= 1e-12 * g11 * g22) return std::nullopt;
    const double s = 0.5 * (g11 * g22 - g22 * g12) / det;
    const double t = 0.5 * (g22 * g11 - g11 * g12) / det;
    const glm::dvec3 x = s * e1 + t * e2;
    return Sphere{a + x, glm::length(x)};
  }
  const glm::dvec3 e1 = subset[1] - a, e2 = subset[2] - a, e3 = subset[3] - a;
  // Rows e1, e2, e3 (glm is column-major, so build the transpose and transpose it).
  const glm::dmat3 rows = glm::transpose(glm::dmat3(e1, e2, e3));
  const double det = glm::determinant(rows);
  if (std::abs(det) <= 1e-9 * glm::length(e1) * glm::length(e2) * glm::length(e3)) {
    return std::nullopt;
  }
  const glm::dvec3 x =
      glm::inverse(rows) * (0.5 * glm::dvec3(glm::dot(e1, e1), glm::dot(e2, e2), glm::dot(e3, e3)));
  return Sphere{a + x, glm::length(x)};
}

// The minimal enclosing sphere passes through some 1..4 of the points: try every subset.
Sphere brute_force_minimal_sphere(const std::vector<glm::dvec3>& points) {
  Sphere best{glm::dvec3(0.0), std::numeric_limits<double>::infinity()};
  const size_t n = points.size();
  std::vector<glm::dvec3> subset;
  const auto consider = [&]() {
    const std::optional<Sphere> sphere = circumsphere_in_affine_hull(subset);
    if (!sphere || sphere->radius >= best.radius) return;
    if (max_distance(points, sphere->center) <= sphere->radius * (1.0 + 1e-9) + 1e-12) {
      best = *sphere;
    }
  };
  for (size_t i = 0; i < n; ++i) {
    subset = {points[i]};
    consider();
    for (size_t j = i + 1; j < n; ++j) {
      subset = {points[i], points[j]};
      consider();
      for (size_t k = j + 1; k < n; ++k) {
        subset = {points[i], points[j], points[k]};
        consider();
        for (size_t l = k + 1; l < n; ++l) {
          subset = {points[i], points[j], points[k], points[l]};
          consider();
        }
      }
    }
  }
  return best;
}

void check_encloses(const Sphere& sphere, const std::vector<glm::dvec3>& points) {
  CHECK(max_distance(points, sphere.center) <= sphere.radius);
}

void check_sphere(const Sphere& actual, const glm::dvec3& center, double radius, double tolerance) {
  INFO("centre (" << actual.center.x << ", " << actual.center.y << ", " << actual.center.z
                  << ") radius " << actual.radius);
  CHECK(glm::distance(actual.center, center) <= tolerance);
  CHECK(std::abs(actual.radius - radius) <= tolerance);
}

glm::dvec3 random_unit_vector(std::mt19937& rng) {
  std::normal_distribution<double> gaussian;
  for (;;) {
    const glm::dvec3 v(gaussian(rng), gaussian(rng), gaussian(rng));
    const double length = glm::length(v);
    if (length > 1e-6) return v / length;
  }
}

}  // namespace

TEST_CASE("minimal enclosing sphere matches brute force on small random sets", "[geom][render]") {
  std::mt19937 rng(20240611u);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  std::uniform_int_distribution<int> count(1, 10);
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<glm::dvec3> points(size_t(count(rng)));
    // Alternate isotropic clouds and flattened ones, whose spheres are usually set by 2 or 3
    // points rather than 4.
    const glm::dvec3 scale = trial % 3 == 0 ? glm::dvec3(1.0, 0.2, 0.05) : glm::dvec3(1.0);
    for (glm::dvec3& p : points) {
      p = glm::dvec3(5.0, -3.0, 2.0) +
          scale * glm::dvec3(coordinate(rng), coordinate(rng), coordinate(rng));
    }
    const Sphere expected = brute_force_minimal_sphere(points);
    const Sphere actual = matgeom::minimal_enclosing_sphere(points);
    INFO("trial " << trial << ", " << points.size() << " points");
    check_encloses(actual, points);
    check_sphere(actual, expected.center, expected.radius, 1e-9);
  }
}

TEST_CASE("points on a known sphere give that sphere", "[geom][render]") {
  std::mt19937 rng(7u);
  const glm::dvec3 center(1.0, 2.0, -3.0);
  const double radius = 0.7;
  std::vector<glm::dvec3> points;
  for (int k = 0; k < 2000; ++k) points.push_back(center + radius * random_unit_vector(rng));
  const Sphere sphere = matgeom::minimal_enclosing_sphere(points);
  check_encloses(sphere, points);
  check_sphere(sphere, center, radius, 1e-9);

  // Adding interior points changes nothing.
  for (int k = 0; k < 2000; ++k) {
    points.push_back(center +
                     0.99 * radius * std::cbrt(double(k) / 2000.0) * random_unit_vector(rng));
  }
  check_sphere(matgeom::minimal_enclosing_sphere(points), center, radius, 1e-9);
}

TEST_CASE("box corners and a regular tetrahedron", "[geom][render]") {
  std::vector<glm::dvec3> box;
  for (int v = 0; v < 8; ++v) {
    box.emplace_back(10.0 + 1.0 * (v & 1), -4.0 + 2.0 * ((v >> 1) & 1), 0.5 + 3.0 * ((v >> 2) & 1));
  }
  check_sphere(matgeom::minimal_enclosing_sphere(box), glm::dvec3(10.5, -3.0, 2.0),
               0.5 * std::sqrt(1.0 + 4.0 + 9.0), 1e-12);

  // Regular tetrahedron with vertices at alternate corners of the cube [-1, 1]^3: circumcentre
  // at the origin, circumradius sqrt(3).
  const std::vector<glm::dvec3> tetrahedron = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  check_sphere(matgeom::minimal_enclosing_sphere(tetrahedron), glm::dvec3(0.0), std::sqrt(3.0),
               1e-12);

  // Obtuse triangle: the sphere is the diametral sphere of the longest edge, not the
  // circumcircle.
  const std::vector<glm::dvec3> obtuse = {{-2, 0, 0}, {2, 0, 0}, {0.3, 0.5, 0}};
  check_sphere(matgeom::minimal_enclosing_sphere(obtuse), glm::dvec3(0.0), 2.0, 1e-12);
}

TEST_CASE("degenerate point sets", "[geom][render]") {
  SECTION("empty") {
    const Sphere sphere = matgeom::minimal_enclosing_sphere(std::vector<glm::dvec3>{});
    CHECK(sphere.center == glm::dvec3(0.0));
    CHECK(sphere.radius == 0.0);
  }
  SECTION("one point") {
    check_sphere(matgeom::minimal_enclosing_sphere(std::vector<glm::dvec3>{{3, 4, 5}}),
                 glm::dvec3(3, 4, 5), 0.0, 0.0);
  }
  SECTION("the same point many times") {
    const std::vector<glm::dvec3> points(1000, glm::dvec3(-1.5, 0.25, 7.0));
    check_sphere(matgeom::minimal_enclosing_sphere(points), glm::dvec3(-1.5, 0.25, 7.0), 0.0, 0.0);
  }
  SECTION("two distinct points, repeated") {
    std::vector<glm::dvec3> points;
    for (int k = 0; k < 50; ++k) {
      points.emplace_back(0, 0, 0);
      points.emplace_back(0, 6, 8);
    }
    check_sphere(matgeom::minimal_enclosing_sphere(points), glm::dvec3(0, 3, 4), 5.0, 1e-12);
  }
  SECTION("collinear points") {
    // Points along a line from a to b: the diametral sphere of the two ends.
    const glm::dvec3 a(1, 2, 3), b(4, -2, 15);
    std::vector<glm::dvec3> points;
    for (int k = 0; k <= 100; ++k) points.push_back(a + (double((k * 37) % 101) / 100.0) * (b - a));
    check_sphere(matgeom::minimal_enclosing_sphere(points), 0.5 * (a + b),
                 0.5 * glm::distance(a, b), 1e-12);
  }
  SECTION("coplanar points on a circle") {
    // 64 points on a circle of radius 2 in a tilted plane, plus its centre: every 4-point
    // support is coplanar, and the answer is the circle's equatorial sphere.
    const glm::dvec3 center(0.5, -1.0, 2.0);
    const glm::dvec3 u = glm::normalize(glm::dvec3(1, 1, 0));
    const glm::dvec3 v = glm::normalize(glm::dvec3(-1, 1, 1));
    const glm::dvec3 w = glm::normalize(glm::cross(u, v));
    const glm::dvec3 v_orthogonal = glm::cross(w, u);
    std::vector<glm::dvec3> points{center};
    for (int k = 0; k < 64; ++k) {
      const double angle = 2.0 * matbase::kPi * k / 64.0;
      points.push_back(center + 2.0 * (std::cos(angle) * u + std::sin(angle) * v_orthogonal));
    }
    check_sphere(matgeom::minimal_enclosing_sphere(points), center, 2.0, 1e-12);
  }
  SECTION("nearly coplanar points") {
    std::mt19937 rng(3u);
    std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
    std::vector<glm::dvec3> points;
    for (int k = 0; k < 9; ++k) {
      points.emplace_back(coordinate(rng), coordinate(rng), 1e-13 * coordinate(rng));
    }
    const Sphere expected = brute_force_minimal_sphere(points);
    const Sphere actual = matgeom::minimal_enclosing_sphere(points);
    check_encloses(actual, points);
    check_sphere(actual, expected.center, expected.radius, 1e-9);
  }
}

TEST_CASE("minimal enclosing sphere is deterministic and order-independent", "[geom][render]") {
  std::mt19937 rng(11u);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  std::vector<glm::dvec3> points(5000);
  for (glm::dvec3& p : points) p = glm::dvec3(coordinate(rng), coordinate(rng), coordinate(rng));

  const Sphere first = matgeom::minimal_enclosing_sphere(points);
  const Sphere second = matgeom::minimal_enclosing_sphere(points);
  CHECK(first.center == second.center);
  CHECK(first.radius == second.radius);

  const std::vector<glm::dvec3> reversed(points.rbegin(), points.rend());
  check_sphere(matgeom::minimal_enclosing_sphere(reversed), first.center, first.radius, 1e-12);
}

TEST_CASE("float overload agrees with the double one", "[geom][render]") {
  const std::vector<glm::vec3> points = {{0, 0, 0}, {2, 0, 0}, {1, 1, 0}, {1, 0.5f, 0.25f}};
  const Sphere sphere = matgeom::minimal_enclosing_sphere(points);
  check_sphere(sphere, glm::dvec3(1, 0, 0), 1.0, 1e-12);
}

TEST_CASE("non-finite points are rejected", "[geom][render]") {
  const std::vector<glm::dvec3> points = {{0, 0, 0},
                                          {std::numeric_limits<double>::quiet_NaN(), 0, 0}};
  CHECK_THROWS_AS(matgeom::minimal_enclosing_sphere(points), std::invalid_argument);
}

TEST_CASE("one million points in bounded time and stack", "[geom][render]") {
  // Uniform in the cube [-1, 1]^3 around (100, 200, 300), plus the cube's 8 corners: the
  // minimal sphere is the corners' sphere, radius sqrt(3). Sorted input (increasing x) is the
  // worst case for an algorithm without the random visiting order.
  std::mt19937 rng(5u);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  const glm::dvec3 center(100.0, 200.0, 300.0);
  std::vector<glm::dvec3> points(1000000);
  for (size_t k = 0; k < points.size(); ++k) {
    const double x = -1.0 + 2.0 * double(k) / double(points.size());
    points[k] = center + glm::dvec3(x, coordinate(rng), coordinate(rng));
  }
  for (int v = 0; v < 8; ++v) {
    points.push_back(center +
                     glm::dvec3(v & 1 ? 1.0 : -1.0, v & 2 ? 1.0 : -1.0, v & 4 ? 1.0 : -1.0));
  }
  const auto start = std::chrono::steady_clock::now();
  const Sphere sphere = matgeom::minimal_enclosing_sphere(points);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  INFO("took " << seconds << " s");
  check_encloses(sphere, points);
  check_sphere(sphere, center, std::sqrt(3.0), 1e-9);
  // Expected linear time: well under a second optimised; a generous bound for debug builds.
  CHECK(seconds < 20.0);
}
