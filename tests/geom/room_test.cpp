// The room an object stands in: every surface faces the inside, the parts are named, the UVs have
// the length asked for, a closed box has no gap, and bad measurements are refused.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <set>
#include <tuple>

#include <glm/gtc/constants.hpp>

#include "matgeom/mesh.h"
#include "matgeom/room.h"
#include "matgeom/uv/uv_scale.h"

namespace {

using matgeom::RoomSpec;
using matgeom::RoomWalls;
using matgeom::TriangleMesh;

glm::dvec3 position(const TriangleMesh& mesh, uint32_t vertex) { return glm::dvec3(mesh.positions[vertex]); }

// The triangle's normal by its winding (counter-clockwise = front), unit length.
glm::dvec3 winding_normal(const TriangleMesh& mesh, size_t t) {
  const glm::uvec3 tri = mesh.triangles[t];
  return glm::normalize(glm::cross(position(mesh, tri[1]) - position(mesh, tri[0]), position(mesh, tri[2]) - position(mesh, tri[0])));
}

glm::dvec3 triangle_centre(const TriangleMesh& mesh, size_t t) {
  const glm::uvec3 tri = mesh.triangles[t];
  return (position(mesh, tri[0]) + position(mesh, tri[1]) + position(mesh, tri[2])) / 3.0;
}

// Every triangle's winding and vertex normals face `inside`, a point within the room.
void check_faces_inside(const TriangleMesh& mesh, const glm::dvec3& inside) {
  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    const glm::dvec3 n = winding_normal(mesh, t);
    INFO("triangle " << t);
    CHECK(glm::dot(n, inside - triangle_centre(mesh, t)) > 0.0);
    for (int k = 0; k < 3; ++k) {
      const glm::dvec3 vertex_normal(mesh.normals[mesh.triangles[t][k]]);
      CHECK(glm::length(vertex_normal) == Approx(1.0).epsilon(1e-6));
      CHECK(glm::dot(vertex_normal, n) > 0.7);
    }
  }
}

std::set<std::string> part_names(const TriangleMesh& mesh) { return {mesh.part_names.begin(), mesh.part_names.end()}; }

}  // namespace

TEST_CASE("A floor alone is one square at the floor's height, facing up, its UVs in the length asked for", "[geom]") {
  RoomSpec spec;
  spec.floor_center = {1.0, -2.0, 0.25};
  spec.half_width = 3.0;
  spec.metres_per_uv = 0.5;
  const TriangleMesh mesh = matgeom::room_mesh(spec);
  REQUIRE_NOTHROW(matgeom::validate_mesh(mesh, "room"));
  CHECK(part_names(mesh) == std::set<std::string>{"floor"});
  CHECK(matgeom::surface_area(mesh) == Approx(36.0));
  for (const glm::vec3& p : mesh.positions) CHECK(p.z == 0.25f);
  check_faces_inside(mesh, {1.0, -2.0, 1.0});
  CHECK(matgeom::metres_per_uv_unit(mesh, 0).value() == Approx(0.5));
  REQUIRE(mesh.tangents.size() == mesh.positions.size());
}

TEST_CASE("A box room with a ceiling is closed, every face looking in", "[geom]") {
  RoomSpec spec;
  spec.half_width = 2.0;
  spec.height = 3.0;
  spec.walls = RoomWalls::Box;
  spec.ceiling = true;
  spec.turn_z = 0.3;
  const TriangleMesh mesh = matgeom::room_mesh(spec);
  REQUIRE_NOTHROW(matgeom::validate_mesh(mesh, "room"));
  CHECK(part_names(mesh) == std::set<std::string>{"floor", "walls", "ceiling"});
  // Floor and ceiling 4 x 4, four walls 4 x 3.
  CHECK(matgeom::surface_area(mesh) == Approx(2 * 16.0 + 4 * 12.0));
  check_faces_inside(mesh, {0.1, -0.2, 1.4});
  // Closed: every edge is shared by exactly two triangles once equal corners are joined.
  std::map<std::pair<std::tuple<long, long, long>, std::tuple<long, long, long>>, int> edges;
  const auto key = [&](uint32_t v) {
    const glm::dvec3 p = position(mesh, v) * 1e4;
    return std::tuple<long, long, long>(std::lround(p.x), std::lround(p.y), std::lround(p.z));
  };
  for (const glm::uvec3& tri : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      auto a = key(tri[k]), b = key(tri[(k + 1) % 3]);
      if (b < a) std::swap(a, b);
      ++edges[{a, b}];
    }
  for (const auto& [edge, count] : edges) CHECK(count == 2);
  // The walls' UVs have the requested length too.
  CHECK(matgeom::metres_per_uv_unit(mesh, 1).value() == Approx(1.0));
}

TEST_CASE("A cyclorama curves from the floor into one backdrop, smooth across the cove, turned as asked", "[geom]") {
  RoomSpec spec;
  spec.half_width = 2.0;
  spec.height = 2.5;
  spec.walls = RoomWalls::Cyclorama;
  spec.cove_radius = 0.6;
  spec.turn_z = 0.5 * glm::pi<double>();  // the backdrop from +Y to -X
  const TriangleMesh mesh = matgeom::room_mesh(spec);
  REQUIRE_NOTHROW(matgeom::validate_mesh(mesh, "room"));
  CHECK(part_names(mesh) == std::set<std::string>{"floor", "walls"});
  check_faces_inside(mesh, {0.0, 0.0, 1.0});
  double lowest_x = 0.0, highest_z = 0.0;
  for (const glm::vec3& p : mesh.positions) {
    lowest_x = std::min(lowest_x, static_cast<double>(p.x));
    highest_z = std::max(highest_z, static_cast<double>(p.z));
  }
  CHECK(lowest_x == Approx(-2.0));
  CHECK(highest_z == Approx(2.5));
  // The profile's length: the floor up to the cove, a quarter circle (as 16 chords), the backdrop.
  const double chords = 16 * 2.0 * 0.6 * std::sin(glm::pi<double>() / 64.0);
  CHECK(matgeom::surface_area(mesh) == Approx(4.0 * ((4.0 - 0.6) + chords + (2.5 - 0.6))).epsilon(1e-6));
  // Vertices where the floor meets the cove share one normal (no crease).
  for (size_t v = 0; v < mesh.positions.size(); ++v)
    if (std::abs(mesh.positions[v].z) < 1e-6f) {
      CHECK(mesh.normals[v].z == Approx(1.0f));
      CHECK(std::abs(mesh.normals[v].x) + std::abs(mesh.normals[v].y) < 1e-6f);
    }
}

TEST_CASE("Room measurements that make no room are refused with a sentence", "[geom]") {
  RoomSpec spec;
  spec.half_width = 0.0;
  CHECK(matgeom::room_spec_problem(spec).value().find("half width") != std::string::npos);
  CHECK_THROWS_AS(matgeom::room_mesh(spec), std::invalid_argument);
  spec = RoomSpec();
  spec.ceiling = true;
  CHECK(matgeom::room_spec_problem(spec).value().find("ceiling") != std::string::npos);
  spec = RoomSpec();
  spec.walls = RoomWalls::Cyclorama;
  spec.cove_radius = 5.0;
  CHECK(matgeom::room_spec_problem(spec).value().find("cove") != std::string::npos);
  spec = RoomSpec();
  spec.floor_center.x = std::nan("");
  CHECK(matgeom::room_spec_problem(spec).has_value());
  CHECK_FALSE(matgeom::room_spec_problem(RoomSpec()).has_value());
}
