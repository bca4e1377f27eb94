#include "matgeom/uv/uv_pass.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <random>
#include <stdexcept>

#include <catch2/catch.hpp>

#include "matbase/pi.h"
#include "matgeom/builtin/builtin_objects.h"
#include "matgeom/tangents.h"
#include "matgeom/uv/chart_segmentation.h"
#include "matgeom/uv/uv_distortion.h"
#include "matgeom/uv/uv_packing.h"

// The UV pass: chart segmentation on shapes with known charts, the packer's guarantees on
// random rectangles, and the whole pass on objects from 5 cm to 3 m: texel density on target,
// charts apart by the gutter, no flips, low distortion.

using namespace matgeom;

namespace {

// An axis-aligned box with split vertices per face (as exporters write it), outward normals.
TriangleMesh box(const glm::vec3& size) {
  TriangleMesh mesh;
  const glm::vec3 h = 0.5f * size;
  for (int axis = 0; axis < 3; ++axis)
    for (int side = -1; side <= 1; side += 2) {
      glm::vec3 n(0.0f);
      n[axis] = static_cast<float>(side);
      const glm::vec3 u = glm::vec3(axis == 1 ? 1.0f : 0.0f, axis == 2 ? 1.0f : 0.0f, axis == 0 ? 1.0f : 0.0f);
      const glm::vec3 v = glm::cross(n, u);
      const uint32_t base = static_cast<uint32_t>(mesh.positions.size());
      for (const glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
        mesh.positions.push_back(h * (n + c.x * u + c.y * v));
        mesh.normals.push_back(n);
      }
      mesh.triangles.emplace_back(base, base + 1, base + 2);
      mesh.triangles.emplace_back(base, base + 2, base + 3);
    }
  return mesh;
}

// A closed cylinder: smooth side, flat caps, radius r, height h.
TriangleMesh closed_cylinder(float r, float h, int segments) {
  TriangleMesh mesh;
  for (int ring = 0; ring < 2; ++ring)
    for (int k = 0; k < segments; ++k) {
      const float a = 6.2831853f * static_cast<float>(k) / static_cast<float>(segments);
      mesh.positions.emplace_back(r * std::cos(a), r * std::sin(a), h * static_cast<float>(ring));
    }
  const auto side = [&](int ring, int k) { return static_cast<uint32_t>(ring * segments + k % segments); };
  for (int k = 0; k < segments; ++k) {
    mesh.triangles.emplace_back(side(0, k), side(0, k + 1), side(1, k + 1));
    mesh.triangles.emplace_back(side(0, k), side(1, k + 1), side(1, k));
  }
  const uint32_t bottom = static_cast<uint32_t>(mesh.positions.size());
  mesh.positions.emplace_back(0.0f, 0.0f, 0.0f);
  mesh.positions.emplace_back(0.0f, 0.0f, h);
  for (int k = 0; k < segments; ++k) {
    mesh.triangles.emplace_back(bottom, side(0, k + 1), side(0, k));
    mesh.triangles.emplace_back(bottom + 1, side(1, k), side(1, k + 1));
  }
  return mesh;
}

// A closed latitude-longitude sphere with bumps of relative height `bumps`: curved everywhere,
// with no sharp edge to cut along.
TriangleMesh bumpy_sphere(float radius, float bumps, int rings, int segments) {
  TriangleMesh mesh;
  mesh.positions.emplace_back(0.0f, 0.0f, radius);
  for (int i = 1; i < rings; ++i)
    for (int k = 0; k < segments; ++k) {
      const float theta = matbase::kPiAs<float> * static_cast<float>(i) / static_cast<float>(rings);
      const float phi = 6.2831853f * static_cast<float>(k) / static_cast<float>(segments);
      const float r = radius * (1.0f + bumps * std::sin(5.0f * theta) * std::sin(6.0f * phi));
      mesh.positions.emplace_back(r * std::sin(theta) * std::cos(phi), r * std::sin(theta) * std::sin(phi),
                                  r * std::cos(theta));
    }
  mesh.positions.emplace_back(0.0f, 0.0f, -radius);
  const uint32_t south = static_cast<uint32_t>(mesh.positions.size() - 1);
  const auto at = [&](int i, int k) { return static_cast<uint32_t>(1 + (i - 1) * segments + k % segments); };
  for (int k = 0; k < segments; ++k) {
    mesh.triangles.emplace_back(0, at(1, k), at(1, k + 1));
    mesh.triangles.emplace_back(south, at(rings - 1, k + 1), at(rings - 1, k));
    for (int i = 1; i + 1 < rings; ++i) {
      mesh.triangles.emplace_back(at(i, k), at(i + 1, k), at(i + 1, k + 1));
      mesh.triangles.emplace_back(at(i, k), at(i + 1, k + 1), at(i, k + 1));
    }
  }
  return mesh;
}

// A flat ring in the z = 0 plane, outer radius 1 and inner radius `inner`: one planar chart,
// which fills only a small part of its bounding box.
TriangleMesh flat_ring(float inner, int segments) {
  TriangleMesh mesh;
  for (int k = 0; k < segments; ++k) {
    const float a = 6.2831853f * static_cast<float>(k) / static_cast<float>(segments);
    mesh.positions.emplace_back(std::cos(a), std::sin(a), 0.0f);
    mesh.positions.emplace_back(inner * std::cos(a), inner * std::sin(a), 0.0f);
  }
  const auto outer_at = [&](int k) { return static_cast<uint32_t>(2 * (k % segments)); };
  for (int k = 0; k < segments; ++k) {
    mesh.triangles.emplace_back(outer_at(k), outer_at(k + 1), outer_at(k + 1) + 1);
    mesh.triangles.emplace_back(outer_at(k), outer_at(k + 1) + 1, outer_at(k) + 1);
  }
  return mesh;
}

TriangleMesh scaled(TriangleMesh mesh, float factor) {
  for (glm::vec3& p : mesh.positions) p *= factor;
  return mesh;
}

// Groups of output triangles that share vertices: the charts (the pass splits vertices at seams).
std::vector<uint32_t> chart_of_triangles(const TriangleMesh& mesh) {
  std::vector<uint32_t> parent(mesh.vertex_count());
  std::iota(parent.begin(), parent.end(), 0u);
  const auto root = [&](uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const glm::uvec3& t : mesh.triangles) parent[root(t.x)] = root(t.y), parent[root(t.z)] = root(t.y);
  std::vector<uint32_t> chart;
  for (const glm::uvec3& t : mesh.triangles) chart.push_back(root(t.x));
  return chart;
}

struct PixelBox {
  int tile;
  glm::dvec2 lower, upper;  // pixels inside the tile
};

// Checks what the pass promises about the layout: UVs inside tiles, charts in one tile each,
// and every two charts of a tile at least the gutter apart (their boxes are, so they are).
void check_layout(const TriangleMesh& mesh, const UvPassOptions& options) {
  const std::vector<uint32_t> chart = chart_of_triangles(mesh);
  std::map<uint32_t, PixelBox> boxes;
  const double r = options.tile_resolution;
  for (size_t t = 0; t < mesh.triangle_count(); ++t)
    for (int c = 0; c < 3; ++c) {
      const glm::dvec2 uv(mesh.uvs[mesh.triangles[t][c]]);
      const int tile = static_cast<int>(std::floor(uv.x));
      REQUIRE(tile >= 0);
      REQUIRE(uv.y >= 0.0);
      REQUIRE(uv.y <= 1.0);
      const glm::dvec2 px((uv.x - tile) * r, uv.y * r);
      auto [it, inserted] = boxes.emplace(chart[t], PixelBox{tile, px, px});
      REQUIRE(it->second.tile == tile);
      it->second.lower = glm::min(it->second.lower, px), it->second.upper = glm::max(it->second.upper, px);
    }
  const double g = options.gutter_pixels - 1e-3;  // float UVs: a thousandth of a pixel
  for (const auto& [id, box] : boxes) {
    CHECK(box.lower.x >= g);
    CHECK(box.lower.y >= g);
    CHECK(box.upper.x <= r - g);
    CHECK(box.upper.y <= r - g);
  }
  for (auto a = boxes.begin(); a != boxes.end(); ++a)
    for (auto b = std::next(a); b != boxes.end(); ++b) {
      if (a->second.tile != b->second.tile) continue;
      const double dx = std::max(a->second.lower.x - b->second.upper.x, b->second.lower.x - a->second.upper.x);
      const double dy = std::max(a->second.lower.y - b->second.upper.y, b->second.lower.y - a->second.upper.y);
      CHECK(std::max(dx, dy) >= g);
    }
}

}  // namespace

TEST_CASE("Charts follow the sharp edges of a box and a cylinder", "[geom]") {
  const TriangleMesh cube = box(glm::vec3(1.0f, 0.6f, 0.4f));
  std::vector<glm::dvec3> positions(cube.positions.begin(), cube.positions.end());
  const std::vector<uint32_t> charts = segment_charts(positions, cube.triangles);
  CHECK(*std::max_element(charts.begin(), charts.end()) == 5);  // one chart per face
  for (size_t t = 0; t < charts.size(); t += 2) CHECK(charts[t] == charts[t + 1]);

  const TriangleMesh cylinder = closed_cylinder(0.3f, 0.5f, 48);
  positions.assign(cylinder.positions.begin(), cylinder.positions.end());
  ChartOptions options;
  options.planarity_bound_degrees = 70.0;
  const std::vector<uint32_t> cylinder_charts = segment_charts(positions, cylinder.triangles, options);
  const uint32_t count = *std::max_element(cylinder_charts.begin(), cylinder_charts.end()) + 1;
  // Caps are cut from the side at the 90-degree rim; the side, whose normals turn through
  // 360 degrees, needs at least 360 / (2 x 70) -> 3 charts.
  CHECK(count >= 5);
  CHECK(count <= 8);
  for (size_t t = 2 * 48; t < cylinder.triangle_count(); ++t) {
    const bool bottom_cap = t % 2 == 0;
    CHECK(cylinder_charts[t] == cylinder_charts[bottom_cap ? 2 * 48 : 2 * 48 + 1]);
  }
}

TEST_CASE("Packed rectangles never overlap and keep the gutter", "[geom]") {
  std::mt19937 rng(0x5eed0005);
  std::uniform_int_distribution<int> side(1, 300);
  std::vector<glm::ivec2> sizes(400);
  for (glm::ivec2& s : sizes) s = glm::ivec2(side(rng), side(rng));
  const PackingOptions options{1024, 2};
  const Packing packing = pack_rectangles(sizes, options);
  double area = 0.0;
  for (size_t i = 0; i < sizes.size(); ++i) {
    const PackedRectangle& a = packing.rectangles[i];
    area += double(sizes[i].x) * sizes[i].y;
    CHECK(a.origin.x >= 2);
    CHECK(a.origin.y >= 2);
    CHECK(a.origin.x + sizes[i].x <= 1024 - 2);
    CHECK(a.origin.y + sizes[i].y <= 1024 - 2);
    for (size_t j = i + 1; j < sizes.size(); ++j) {
      const PackedRectangle& b = packing.rectangles[j];
      if (a.tile != b.tile) continue;
      const int dx = std::max(a.origin.x - (b.origin.x + sizes[j].x), b.origin.x - (a.origin.x + sizes[i].x));
      const int dy = std::max(a.origin.y - (b.origin.y + sizes[j].y), b.origin.y - (a.origin.y + sizes[i].y));
      CHECK(std::max(dx, dy) >= 2);
    }
  }
  // Shelves of decreasing height waste at most the height differences within a shelf and the
  // ends of shelves: well over half of the occupied area is used.
  const double occupied = (packing.tiles - 1.0) * 1024 * 1024 + double(packing.last_tile_width) * packing.last_tile_height;
  CHECK(area / occupied > 0.6);
  CHECK_THROWS_AS(pack_rectangles({glm::ivec2(1021, 10)}, options), std::invalid_argument);
  CHECK_THROWS_AS(pack_rectangles({glm::ivec2(0, 10)}, options), std::invalid_argument);
}

TEST_CASE("A few charts pack densely into a corner of a large tile, not along a strip", "[geom]") {
  // Thirty leg-like strips and some small pieces: one full-width shelf would be 4096 pixels long
  // and as tall as a strip, mostly empty.
  std::vector<glm::ivec2> sizes(30, glm::ivec2(300, 24));
  for (int k = 0; k < 20; ++k) sizes.emplace_back(10 + k, 12);
  const PackingOptions options{4096, 2};
  const Packing packing = pack_rectangles(sizes, options);
  double area = 0.0;
  for (const glm::ivec2& size : sizes) area += double(size.x) * size.y;
  CHECK(packing.tiles == 1);
  CHECK(area / (double(packing.last_tile_width) * packing.last_tile_height) > 0.7);
}

TEST_CASE("The UV pass reaches the target texel density from 5 cm to 3 m", "[geom]") {
  TriangleMesh unit_box = box(glm::vec3(1.0f, 0.6f, 0.4f));
  TriangleMesh cylinder = closed_cylinder(0.5f, 1.0f, 40);
  compute_vertex_normals(cylinder);
  for (const float size : {0.05f, 0.3f, 1.0f, 3.0f})
    for (const double s : {0.1, 0.5, 1.0, 2.0}) {
      for (const TriangleMesh* shape : std::array<const TriangleMesh*, 2>{&unit_box, &cylinder}) {
        UvPassOptions options;  // the default 4096-pixel tiles
        options.texel_density_scale = s;
        const TriangleMesh mesh = scaled(*shape, size);
        const UvPassResult result = uv_pass(mesh, options);
        REQUIRE(result.parts.size() == 1);
        const UvPartReport& report = result.parts[0];
        INFO("size " << size << " m, s = " << s << ": target " << report.target_density << " px/m, achieved "
                     << report.achieved_density << ", " << report.charts << " charts in " << report.tiles
                     << " tiles, efficiency " << report.packing_efficiency);
        CHECK(report.achieved_density == Approx(report.target_density).epsilon(0.01));
        CHECK(report.distortion.flipped_triangles == 0);
        CHECK(report.distortion.angle_mean < 0.05);
        CHECK(report.packing_efficiency > 0.2);
        CHECK(report.packing_efficiency <= 1.0);
        CHECK(result.mesh.triangle_count() == mesh.triangle_count());
        check_layout(result.mesh, options);
        // The same surface: every triangle keeps its corner positions.
        for (size_t t = 0; t < mesh.triangle_count(); ++t)
          for (int c = 0; c < 3; ++c)
            CHECK(result.mesh.positions[result.mesh.triangles[t][c]] == mesh.positions[mesh.triangles[t][c]]);
      }
    }
}

TEST_CASE("Charts too stretched or too sparse in their box are halved until within the bounds", "[geom]") {
  // Each chart of the output, measured on its own: L2 stretch (Sander et al. 2001) and the
  // fraction of its UV box it covers.
  const auto check_charts = [](const TriangleMesh& mesh, const UvPassOptions& options) {
    const std::vector<uint32_t> chart = chart_of_triangles(mesh);
    std::map<uint32_t, std::vector<glm::uvec3>> triangles_of;
    for (size_t t = 0; t < mesh.triangle_count(); ++t) triangles_of[chart[t]].push_back(mesh.triangles[t]);
    std::vector<glm::dvec3> positions(mesh.positions.begin(), mesh.positions.end());
    std::vector<glm::dvec2> uvs(mesh.uvs.begin(), mesh.uvs.end());
    for (const auto& [id, triangles] : triangles_of) {
      if (triangles.size() == 1) continue;  // a single triangle cannot be split
      glm::dvec2 lower(1e9), upper(-1e9);
      double area = 0.0;
      for (const glm::uvec3& t : triangles) {
        for (int c = 0; c < 3; ++c) lower = glm::min(lower, uvs[t[c]]), upper = glm::max(upper, uvs[t[c]]);
        const glm::dvec2 e1 = uvs[t.y] - uvs[t.x], e2 = uvs[t.z] - uvs[t.x];
        area += 0.5 * std::abs(e1.x * e2.y - e1.y * e2.x);
      }
      INFO("chart of " << triangles.size() << " triangles");
      CHECK(measure_uv_distortion(positions, triangles, uvs).stretch_l2 <= options.max_stretch * (1.0 + 1e-3));
      CHECK(area >= options.min_box_fill * (upper.x - lower.x) * (upper.y - lower.y) * (1.0 - 1e-3));
    }
  };
  const TriangleMesh sphere = bumpy_sphere(0.3f, 0.15f, 48, 96);
  UvPassOptions unbounded;
  unbounded.max_stretch = 1e9;
  CHECK(uv_pass(sphere, unbounded).parts[0].distortion.stretch_l2 > 1.03);  // what LSCM alone gives
  for (const double bound : {1.2, 1.03}) {
    UvPassOptions options;
    options.max_stretch = bound;
    const UvPassResult result = uv_pass(sphere, options);
    INFO("stretch bound " << bound << ": " << result.parts[0].charts << " charts");
    // Every chart has the same density, so the part's stretch is their area-weighted RMS.
    CHECK(result.parts[0].distortion.stretch_l2 <= bound * (1.0 + 1e-3));
    CHECK(result.parts[0].achieved_density == Approx(result.parts[0].target_density).epsilon(0.01));
    check_charts(result.mesh, options);
  }
  // A thin flat ring is a single isometric chart covering pi (1 - 0.9^2) / 4 = 15% of its box.
  const TriangleMesh ring = flat_ring(0.9f, 96);
  UvPassOptions whole;
  whole.min_box_fill = 0.0;
  CHECK(uv_pass(ring, whole).parts[0].charts == 1);
  const UvPassResult split = uv_pass(ring);
  CHECK(split.parts[0].charts > 1);
  CHECK(split.parts[0].distortion.stretch_l2 == Approx(1.0).epsilon(1e-3));
  check_charts(split.mesh, UvPassOptions{});
  check_layout(split.mesh, UvPassOptions{});
}

TEST_CASE("The target density follows the paper's formula", "[geom]") {
  // d = 512 px/m at l = sqrt(A / pi) = 1 m; inversely proportional to l.
  CHECK(target_texel_density(matbase::kPi) == Approx(512.0));
  CHECK(target_texel_density(4.0 * matbase::kPi) == Approx(256.0));
  CHECK(target_texel_density(0.01 * matbase::kPi) == Approx(5120.0));
}

TEST_CASE("Charts too large for a tile are split and still reach the density", "[geom]") {
  UvPassOptions options;
  options.tile_resolution = 256;
  options.texel_density_scale = 2.0;
  TriangleMesh plane;  // a 2 m x 1 m plate of 20 x 10 quads: one planar chart, far wider than a tile
  for (int j = 0; j <= 10; ++j)
    for (int i = 0; i <= 20; ++i) plane.positions.emplace_back(0.1f * i, 0.1f * j, 0.0f);
  for (int j = 0; j < 10; ++j)
    for (int i = 0; i < 20; ++i) {
      const uint32_t a = static_cast<uint32_t>(j * 21 + i);
      plane.triangles.emplace_back(a, a + 1, a + 22);
      plane.triangles.emplace_back(a, a + 22, a + 21);
    }
  const UvPassResult result = uv_pass(plane, options);
  const UvPartReport& report = result.parts[0];
  INFO(report.charts << " charts in " << report.tiles << " tiles");
  CHECK(report.charts > 1);
  CHECK(report.tiles > 1);
  CHECK(report.shrunk_charts == 0);
  CHECK(report.achieved_density == Approx(report.target_density).epsilon(0.01));
  CHECK(report.distortion.angle_max < 1e-4);  // planar pieces unroll exactly
  check_layout(result.mesh, options);
}

TEST_CASE("The UV pass keeps parts and existing UVs on request", "[geom]") {
  TriangleMesh mesh = box(glm::vec3(0.4f, 0.4f, 0.8f));
  mesh.triangle_parts.assign(mesh.triangle_count(), 0);
  for (size_t t = 8; t < mesh.triangle_count(); ++t) mesh.triangle_parts[t] = 1;
  mesh.part_names = {"sides", "top and bottom"};
  const UvPassResult result = uv_pass(mesh);
  REQUIRE(result.parts.size() == 2);
  CHECK(result.parts[0].part == "sides");
  CHECK(result.parts[1].part == "top and bottom");
  CHECK(result.mesh.triangle_parts == mesh.triangle_parts);
  CHECK(result.mesh.tangents.size() == result.mesh.vertex_count());
  // Each part starts at tile 0 (parts texture separate images).
  for (const UvPartReport& report : result.parts) CHECK(report.tiles == 1);

  UvPassOptions keep;
  keep.keep_existing_uvs = true;
  const UvPassResult kept = uv_pass(result.mesh, keep);
  CHECK(kept.mesh.uvs == result.mesh.uvs);
  CHECK(kept.mesh.triangles == result.mesh.triangles);
  CHECK(kept.parts[0].achieved_density == Approx(result.parts[0].achieved_density).epsilon(1e-6));

  UvPassOptions bad;
  bad.texel_density_scale = 0.0;
  CHECK_THROWS_AS(uv_pass(mesh, bad), std::invalid_argument);
}

TEST_CASE("The UV pass gives finite UVs for degenerate triangles and parts", "[geom]") {
  TriangleMesh mesh = box(glm::vec3(0.3f, 0.2f, 0.1f));
  mesh.triangle_parts.assign(mesh.triangle_count(), 0);
  mesh.part_names = {"box", "slivers"};
  // Part 1: only zero-area triangles (a repeated vertex, three collinear points).
  const uint32_t base = static_cast<uint32_t>(mesh.positions.size());
  for (const glm::vec3 p : {glm::vec3(1, 0, 0), glm::vec3(2, 0, 0), glm::vec3(3, 0, 0)}) {
    mesh.positions.push_back(p);
    mesh.normals.emplace_back(0.0f, 0.0f, 1.0f);
  }
  mesh.triangles.emplace_back(base, base + 1, base + 2);
  mesh.triangles.emplace_back(base, base, base + 1);
  mesh.triangle_parts.insert(mesh.triangle_parts.end(), 2, 1u);
  // A sliver inside part 0 as well.
  mesh.triangles.emplace_back(0u, 0u, 1u);
  mesh.triangle_parts.push_back(0u);
  const UvPassResult result = uv_pass(mesh);
  for (const glm::vec2& uv : result.mesh.uvs) {
    CHECK(std::isfinite(uv.x));
    CHECK(std::isfinite(uv.y));
  }
  for (const glm::vec4& t : result.mesh.tangents) CHECK(std::isfinite(t.x + t.y + t.z + t.w));
  REQUIRE(result.parts.size() == 2);
  CHECK(result.parts[0].achieved_density == Approx(result.parts[0].target_density).epsilon(0.01));
  CHECK(result.parts[1].target_density == 0.0);
}
