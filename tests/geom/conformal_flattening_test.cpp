#include "matgeom/uv/conformal_flattening.h"

#include <cmath>
#include <stdexcept>

#include <catch2/catch.hpp>

#include "matbase/pi.h"
#include "matgeom/uv/uv_distortion.h"

// LSCM on surfaces whose best flattening is known: developable patches (a cylinder or cone cut
// open unrolls isometrically, so a conformal map must have no distortion at all) and a
// hemisphere (conformal maps exist, angle distortion only from the discretisation; area
// distortion is forced, by a factor bounded by that of the stereographic projection).

using namespace matgeom;

namespace {

struct Surface {
  std::vector<glm::dvec3> positions;
  std::vector<glm::uvec3> triangles;
};

// A grid of (nu + 1) x (nv + 1) vertices mapped through `point(s, t)`, s, t in [0, 1].
template <class Point>
Surface grid_surface(int nu, int nv, Point point) {
  Surface s;
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) s.positions.push_back(point(double(i) / nu, double(j) / nv));
  const auto index = [nu](int i, int j) { return static_cast<uint32_t>(j * (nu + 1) + i); };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      s.triangles.emplace_back(index(i, j), index(i + 1, j), index(i + 1, j + 1));
      s.triangles.emplace_back(index(i, j), index(i + 1, j + 1), index(i, j + 1));
    }
  return s;
}

// Three-quarters of a cylinder: every quad is planar (a chord rectangle), so the triangulated
// patch is exactly developable.
Surface cylinder_patch(const glm::dvec3& offset = glm::dvec3(0.0)) {
  return grid_surface(36, 8, [&](double s, double t) {
    const double angle = 1.5 * matbase::kPi * s;
    return offset + glm::dvec3(0.3 * std::cos(angle), 0.3 * std::sin(angle), 0.5 * t);
  });
}

// A cone frustum patch: its quads lie on pairs of rulings through the apex, so it is exactly
// developable too.
Surface cone_patch() {
  return grid_surface(30, 6, [](double s, double t) {
    const double angle = 1.2 * matbase::kPi * s;
    const double along = 0.2 + 0.8 * t;  // distance from the apex along a ruling, scaled
    return along * glm::dvec3(0.5 * std::cos(angle), 0.5 * std::sin(angle), 0.7);
  });
}

// The upper hemisphere of radius 0.4, from the pole to the equator in `rings` rings.
Surface hemisphere(int rings) {
  Surface s;
  const int segments = 3 * rings;
  s.positions.emplace_back(0.0, 0.0, 0.4);
  for (int r = 1; r <= rings; ++r)
    for (int k = 0; k < segments; ++k) {
      const double polar = 0.5 * matbase::kPi * r / rings, azimuth = 2.0 * matbase::kPi * k / segments;
      s.positions.push_back(0.4 * glm::dvec3(std::sin(polar) * std::cos(azimuth),
                                             std::sin(polar) * std::sin(azimuth), std::cos(polar)));
    }
  const auto ring_vertex = [&](int r, int k) { return static_cast<uint32_t>(1 + (r - 1) * segments + k % segments); };
  for (int k = 0; k < segments; ++k) s.triangles.emplace_back(0u, ring_vertex(1, k), ring_vertex(1, k + 1));
  for (int r = 1; r < rings; ++r)
    for (int k = 0; k < segments; ++k) {
      s.triangles.emplace_back(ring_vertex(r, k), ring_vertex(r + 1, k), ring_vertex(r + 1, k + 1));
      s.triangles.emplace_back(ring_vertex(r, k), ring_vertex(r + 1, k + 1), ring_vertex(r, k + 1));
    }
  return s;
}

void check_isometric(const Surface& s, const std::vector<glm::dvec2>& uvs) {
  const UvDistortion d = measure_uv_distortion(s.positions, s.triangles, uvs);
  CHECK(d.angle_mean < 1e-6);
  CHECK(d.angle_max < 1e-5);
  CHECK(d.stretch_l2 == Approx(1.0).margin(1e-6));
  CHECK(d.stretch_linf == Approx(1.0).margin(1e-5));
  CHECK(d.flipped_triangles == 0);
  CHECK(d.degenerate_triangles == 0);
  // Isometric up to one scale (the pins sit at their 3-D chord distance, not their distance in
  // the unrolled plane): every edge is scaled by the same factor.
  const glm::uvec3 first = s.triangles.front();
  const double scale = glm::distance(uvs[first.x], uvs[first.y]) / glm::distance(s.positions[first.x], s.positions[first.y]);
  CHECK(scale > 0.5);
  CHECK(scale < 2.0);
  for (const glm::uvec3& t : s.triangles)
    for (int c = 0; c < 3; ++c) {
      const uint32_t a = t[c], b = t[(c + 1) % 3];
      CHECK(glm::distance(uvs[a], uvs[b]) == Approx(scale * glm::distance(s.positions[a], s.positions[b])).epsilon(1e-6));
    }
}

}  // namespace

TEST_CASE("LSCM unrolls developable patches without distortion", "[geom]") {
  SECTION("cylinder") {
    const Surface s = cylinder_patch();
    check_isometric(s, flatten_lscm(s.positions, s.triangles));
  }
  SECTION("cone") {
    const Surface s = cone_patch();
    check_isometric(s, flatten_lscm(s.positions, s.triangles));
  }
  SECTION("two separate patches, flattened each on its own") {
    Surface a = cylinder_patch(), b = cylinder_patch(glm::dvec3(2.0, 0.0, 0.0));
    const uint32_t offset = static_cast<uint32_t>(a.positions.size());
    a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
    for (glm::uvec3 t : b.triangles) a.triangles.push_back(t + glm::uvec3(offset));
    check_isometric(a, flatten_lscm(a.positions, a.triangles));
  }
}

TEST_CASE("LSCM maps a hemisphere conformally up to the discretisation", "[geom]") {
  const auto distortion = [](int rings) {
    const Surface s = hemisphere(rings);
    return measure_uv_distortion(s.positions, s.triangles, flatten_lscm(s.positions, s.triangles));
  };
  const UvDistortion coarse = distortion(16), fine = distortion(32);
  INFO("16 rings: angle mean " << coarse.angle_mean << " max " << coarse.angle_max << ", stretch L2 "
                               << coarse.stretch_l2 << " Linf " << coarse.stretch_linf);
  INFO("32 rings: angle mean " << fine.angle_mean << " max " << fine.angle_max);
  // A smooth conformal map exists; on the piecewise-flat mesh the residual angle distortion is
  // a discretisation error, of the order of the edge length in radians (pi/32 at 16 rings), and
  // it halves when the rings double.
  CHECK(coarse.angle_mean < matbase::kPi / 32.0);
  CHECK(coarse.angle_max < 4.0 * matbase::kPi / 32.0);
  CHECK(fine.angle_mean < 0.6 * coarse.angle_mean);
  CHECK(coarse.flipped_triangles == 0);
  CHECK(fine.flipped_triangles == 0);
  // Area is distorted, as any flattening of a sphere must be. The stereographic projection of
  // the hemisphere onto a disc scales lengths by 2 / (1 + cos polar), between 1 and 2, so its
  // stretch relative to the mean stays within sqrt(2).
  CHECK(coarse.stretch_l2 > 1.01);
  CHECK(coarse.stretch_l2 < 1.2);
  CHECK(coarse.stretch_linf < std::sqrt(2.0) + 0.01);
}

TEST_CASE("LSCM tolerates degenerate triangles and rejects bad indices", "[geom]") {
  Surface s = cylinder_patch();
  const size_t regular = s.triangles.size();
  s.triangles.emplace_back(0u, 0u, 1u);  // a repeated vertex
  // A sliver hanging off the patch: a new vertex on the line through vertices 0 and 1, which
  // only zero-area triangles reach.
  const uint32_t on_line = static_cast<uint32_t>(s.positions.size());
  s.positions.push_back(2.0 * s.positions[1] - s.positions[0]);
  s.triangles.emplace_back(0u, 1u, on_line);
  const std::vector<glm::dvec2> uvs = flatten_lscm(s.positions, s.triangles);
  for (const glm::dvec2& uv : uvs) CHECK(std::isfinite(uv.x + uv.y));
  // The regular triangles are unrolled as before.
  Surface regular_part = s;
  regular_part.triangles.resize(regular);
  regular_part.positions.pop_back();
  std::vector<glm::dvec2> regular_uvs = uvs;
  regular_uvs.pop_back();
  check_isometric(regular_part, regular_uvs);
  s.triangles.emplace_back(0u, 1u, static_cast<uint32_t>(s.positions.size()));
  CHECK_THROWS_AS(flatten_lscm(s.positions, s.triangles), std::invalid_argument);
  CHECK(flatten_lscm({}, {}).empty());
}
