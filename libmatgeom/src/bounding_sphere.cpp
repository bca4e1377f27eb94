#include "matgeom/bounding_sphere.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

namespace matgeom {
namespace {

// A point counts as inside when its squared distance exceeds r^2 by at most this relative
// amount. Without the slack, rounding in the circumsphere makes support points test as outside
// and triggers needless (but harmless) recomputation.
constexpr double kContainmentSlack = 1e-10;

// Support points closer than this to collinear (sine of the angle) or coplanar (normalised
// volume) have no well-conditioned circumsphere; the smaller-support fallback takes over.
constexpr double kDegeneracyTolerance = 1e-10;

// Fixed seed: the visiting order, and so the rounding of the result, is the same on every run.
constexpr uint32_t kShuffleSeed = 0x5eed1991u;

// A ball with negative radius contains nothing: the start of the search with empty support.
struct Ball {
  glm::dvec3 center{0.0};
  double radius_squared = -1.0;
};

bool contains(const Ball& ball, const glm::dvec3& p) {
  const glm::dvec3 d = p - ball.center;
  return glm::dot(d, d) <= ball.radius_squared * (1.0 + kContainmentSlack);
}

double distance_squared(const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 d = a - b;
  return glm::dot(d, d);
}

// Grows `ball` just enough to contain `p`, keeping its centre.
Ball enlarged_to_contain(Ball ball, const glm::dvec3& p) {
  ball.radius_squared = std::max(ball.radius_squared, distance_squared(ball.center, p));
  return ball;
}

Ball ball_through(const glm::dvec3& a) { return {a, 0.0}; }

Ball ball_through(const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 center = 0.5 * (a + b);
  return {center, distance_squared(center, a)};
}

Ball ball_through(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

// Minimal enclosing ball of 3 collinear or 4 coplanar points. Such a ball passes through
// fewer of them: 2 for collinear points, 2 or 3 for coplanar ones. Every candidate is grown to
// hold all the points, so the smallest grown candidate is the minimal ball.
template <size_t N>
Ball smallest_ball_from_smaller_supports(const std::array<glm::dvec3, N>& points) {
  static_assert(N == 3 || N == 4, "only 3 or 4 points can be degenerate support sets");
  Ball best;
  best.radius_squared = std::numeric_limits<double>::infinity();
  const auto consider = [&](Ball candidate) {
    for (const glm::dvec3& p : points) candidate = enlarged_to_contain(candidate, p);
    if (candidate.radius_squared < best.radius_squared) best = candidate;
  };
  for (size_t i = 0; i < N; ++i) {
    for (size_t j = i + 1; j < N; ++j) {
      consider(ball_through(points[i], points[j]));
      if constexpr (N == 4) {
        for (size_t k = j + 1; k < N; ++k) {
          consider(ball_through(points[i], points[j], points[k]));
        }
      }
    }
  }
  return best;
}

// Smallest ball with a, b, c on its boundary: the circumcircle's centre, which for u = b - a,
// v = c - a and w = u x v is a + (|u|^2 (v x w) + |v|^2 (w x u)) / (2 |w|^2).
Ball ball_through(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const glm::dvec3 u = b - a;
  const glm::dvec3 v = c - a;
  const glm::dvec3 w = glm::cross(u, v);
  const double uu = glm::dot(u, u);
  const double vv = glm::dot(v, v);
  const double ww = glm::dot(w, w);
  // |w|^2 = |u|^2 |v|^2 sin^2(angle at a).
  if (!(ww > kDegeneracyTolerance * kDegeneracyTolerance * uu * vv)) {
    return smallest_ball_from_smaller_supports(std::array<glm::dvec3, 3>{a, b, c});
  }
  const glm::dvec3 offset = (uu * glm::cross(v, w) + vv * glm::cross(w, u)) / (2.0 * ww);
  return {a + offset, glm::dot(offset, offset)};
}

// Ball with a, b, c, d on its boundary (their circumsphere): for u = b - a, v = c - a, w = d - a,
// the centre is a + (|u|^2 (v x w) + |v|^2 (w x u) + |w|^2 (u x v)) / (2 u.(v x w)).
Ball ball_through(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                  const glm::dvec3& d) {
  const glm::dvec3 u = b - a;
  const glm::dvec3 v = c - a;
  const glm::dvec3 w = d - a;
  const glm::dvec3 v_cross_w = glm::cross(v, w);
  const double volume = glm::dot(u, v_cross_w);  // six times the tetrahedron's volume
  const double scale = glm::length(u) * glm::length(v) * glm::length(w);
  if (!(std::abs(volume) > kDegeneracyTolerance * scale)) {
    return smallest_ball_from_smaller_supports(std::array<glm::dvec3, 4>{a, b, c, d});
  }
  const glm::dvec3 offset = (glm::dot(u, u) * v_cross_w + glm::dot(v, v) * glm::cross(w, u) +
                             glm::dot(w, w) * glm::cross(u, v)) /
                            (2.0 * volume);
  return {a + offset, glm::dot(offset, offset)};
}

// The points that must lie on the boundary of the ball being built (at most four in 3-D).
struct Support {
  std::array<glm::dvec3, 4> points;
  int size = 0;

  Ball ball() const {
    switch (size) {
      case 1:
        return ball_through(points[0]);
      case 2:
        return ball_through(points[0], points[1]);
      case 3:
        return ball_through(points[0], points[1], points[2]);
      case 4:
        return ball_through(points[0], points[1], points[2], points[3]);
      default:
        return Ball{};  // no support yet: the empty ball, which every point violates
    }
  }
};

// Welzl's recursion with Gaertner's move-to-front list: the smallest ball that encloses
// points[0, count) and has every support point on its boundary. Each nested call adds one
// support point, so the recursion is at most five deep however many points there are. A point
// that forced a new ball is moved to the front, where later scans meet it first.
Ball move_to_front_ball(std::vector<glm::dvec3>& points, size_t count, Support& support) {
  Ball ball = support.ball();
  if (support.size == 4) return ball;
  for (size_t k = 0; k < count; ++k) {
    if (contains(ball, points[k])) continue;
    support.points[support.size++] = points[k];
    ball = move_to_front_ball(points, k, support);
    --support.size;
    std::rotate(points.begin(), points.begin() + static_cast<std::ptrdiff_t>(k),
                points.begin() + static_cast<std::ptrdiff_t>(k) + 1);
  }
  return ball;
}

// Uniform integer in [0, bound) from 64 random bits, by rejection (std::uniform_int_distribution
// is implementation-defined, so it would make the order differ between standard libraries).
uint64_t uniform_below(std::mt19937& rng, uint64_t bound) {
  const uint64_t limit =
      std::numeric_limits<uint64_t>::max() - std::numeric_limits<uint64_t>::max() % bound;
  for (;;) {
    const uint64_t bits = (static_cast<uint64_t>(rng()) << 32) | static_cast<uint64_t>(rng());
    if (bits < limit) return bits % bound;
  }
}

// Fisher-Yates: a random visiting order gives Welzl's expected linear running time whatever
// order the mesh stores its vertices in.
void shuffle_deterministically(std::vector<glm::dvec3>& points) {
  std::mt19937 rng(kShuffleSeed);
  for (size_t i = points.size(); i > 1; --i) {
    const size_t j = static_cast<size_t>(uniform_below(rng, i));
    std::swap(points[i - 1], points[j]);
  }
}

}  // namespace

Sphere minimal_enclosing_sphere(const std::vector<glm::dvec3>& points) {
  if (points.empty()) return Sphere{};
  for (size_t k = 0; k < points.size(); ++k) {
    const glm::dvec3& p = points[k];
    if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))) {
      throw std::invalid_argument("minimal_enclosing_sphere: point " + std::to_string(k) +
                                  " is not finite");
    }
  }

  // Work relative to one of the points: a small object far from the origin keeps its digits
  // in the circumsphere formulas.
  const glm::dvec3 origin = points.front();
  std::vector<glm::dvec3> local(points.size());
  std::transform(points.begin(), points.end(), local.begin(),
                 [&](const glm::dvec3& p) { return p - origin; });
  shuffle_deterministically(local);

  Support support;
  const Ball ball = move_to_front_ball(local, local.size(), support);

  // The containment slack, the degenerate fallbacks and the rounding of the shift back to the
  // caller's frame may each leave a point a hair outside; the radius is therefore taken as the
  // largest distance from the returned centre, so every point is enclosed as computed.
  Sphere sphere{origin + ball.center, 0.0};
  for (const glm::dvec3& p : points)
    sphere.radius = std::max(sphere.radius, glm::distance(p, sphere.center));
  return sphere;
}

Sphere minimal_enclosing_sphere(const std::vector<glm::vec3>& points) {
  return minimal_enclosing_sphere(std::vector<glm::dvec3>(points.begin(), points.end()));
}

}  // namespace matgeom
