#include "matgeom/shading_normals.h"

#include <cmath>
#include <stdexcept>
#include <vector>

#include <catch2/catch.hpp>

// Blender's normals for faces without given ones, against values worked out by hand: a cube's
// vertex normal is the mean of its three face normals (each face meets the corner at 90 degrees,
// however its quad is cut into triangles), and a sharp edge splits it.

using namespace matgeom;

namespace {

// A cube of side 2 about the origin, each face a quad cut into two triangles along a diagonal
// that alternates, so that some corners have one triangle of a face and others two.
TriangleMesh cube() {
  TriangleMesh mesh;
  mesh.positions = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
  const int quads[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  for (int f = 0; f < 6; ++f) {
    const int* q = quads[f];
    if (f % 2 == 0) {
      mesh.triangles.emplace_back(q[0], q[1], q[2]);
      mesh.triangles.emplace_back(q[0], q[2], q[3]);
    } else {
      mesh.triangles.emplace_back(q[1], q[2], q[3]);
      mesh.triangles.emplace_back(q[1], q[3], q[0]);
    }
  }
  return mesh;
}

glm::vec3 face_normal(const TriangleMesh& mesh, size_t t) {
  const glm::uvec3& tri = mesh.triangles[t];
  return glm::normalize(glm::cross(mesh.positions[tri[1]] - mesh.positions[tri[0]], mesh.positions[tri[2]] - mesh.positions[tri[0]]));
}

void check_near(const glm::vec3& actual, const glm::vec3& expected) {
  INFO("actual (" << actual.x << ", " << actual.y << ", " << actual.z << "), expected (" << expected.x << ", " << expected.y
                  << ", " << expected.z << ")");
  CHECK(glm::length(actual - expected) < 1e-6f);
}

// Every corner's normal is its face's.
void check_flat(const TriangleMesh& mesh, const std::vector<glm::vec3>& corners) {
  for (size_t t = 0; t < mesh.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k) check_near(corners[3 * t + k], face_normal(mesh, t));
}

// Every corner's normal is the cube corner's diagonal, (+-1, +-1, +-1) / sqrt 3.
void check_diagonal(const TriangleMesh& mesh, const std::vector<glm::vec3>& corners) {
  for (size_t t = 0; t < mesh.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k) check_near(corners[3 * t + k], glm::normalize(mesh.positions[mesh.triangles[t][k]]));
}

}  // namespace

TEST_CASE("blender_corner_normals: flat faces take their face normal, smooth ones the corner mean", "[geom]") {
  const TriangleMesh mesh = cube();
  SECTION("every face flat") { check_flat(mesh, blender_corner_normals(mesh, {})); }
  SECTION("every face smooth: the mean of the three faces, however a quad is cut") {
    MissingNormals missing;
    missing.smooth.assign(mesh.triangle_count(), true);
    check_diagonal(mesh, blender_corner_normals(mesh, missing));
  }
  SECTION("a smooth face next to flat ones still averages them, as Blender's vertex normals do") {
    MissingNormals missing;
    missing.smooth.assign(mesh.triangle_count(), false);
    missing.smooth[2] = missing.smooth[3] = true;  // the top (+Z) face
    const std::vector<glm::vec3> corners = blender_corner_normals(mesh, missing);
    for (size_t t = 0; t < mesh.triangle_count(); ++t)
      for (int k = 0; k < 3; ++k)
        check_near(corners[3 * t + k], t == 2 || t == 3 ? glm::normalize(mesh.positions[mesh.triangles[t][k]]) : face_normal(mesh, t));
  }
}

TEST_CASE("blender_corner_normals: Auto Smooth splits at edges sharper than its angle", "[geom]") {
  const TriangleMesh mesh = cube();
  MissingNormals missing;
  SECTION("the cube's 90 degree edges are sharp at 30 degrees") {
    missing.auto_smooth_deg = 30.0;
    check_flat(mesh, blender_corner_normals(mesh, missing));
  }
  SECTION("and smooth at 100 degrees") {
    missing.auto_smooth_deg = 100.0;
    check_diagonal(mesh, blender_corner_normals(mesh, missing));
  }
  SECTION("a quad's diagonal is never sharp: a face stays one fan") {
    missing.auto_smooth_deg = 1.0;
    check_flat(mesh, blender_corner_normals(mesh, missing));
  }
}

TEST_CASE("blender_corner_normals: a fan of unequal angles is weighted by the corner angles", "[geom]") {
  // Two triangles meeting at the origin on the edge to (0, 1, 0): one in the plane z = 0 with
  // a 90 degree corner there, one tilted up by 60 degrees about that edge with a 45 degree corner.
  TriangleMesh mesh;
  const double c = std::cos(M_PI / 3.0), s = std::sin(M_PI / 3.0);
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {static_cast<float>(-c), 1, static_cast<float>(s)}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  MissingNormals missing;
  missing.auto_smooth_deg = 90.0;
  const std::vector<glm::vec3> corners = blender_corner_normals(mesh, missing);
  // Face normals (0, 0, 1) and (s, 0, c) after the tilt about +Y; angles at the origin pi/2 and
  // the angle between (0, 1, 0) and (-c, 1, s), which is pi/4 (both legs are 1 and sqrt 2 long).
  const glm::dvec3 expected = glm::normalize(M_PI / 2.0 * glm::dvec3(0, 0, 1) + M_PI / 4.0 * glm::dvec3(s, 0, c));
  check_near(corners[0], glm::vec3(expected));
  check_near(corners[3], glm::vec3(expected));
  // At (1, 0, 0) only the first face is there.
  check_near(corners[1], glm::vec3(0, 0, 1));
}

TEST_CASE("blender_corner_normals: non-manifold edges and flipped neighbours are sharp", "[geom]") {
  // Three fins on one edge from (0, 0, 0) to (0, 0, 1), 120 degrees apart: no edge joins two of them.
  TriangleMesh fins;
  fins.positions = {{0, 0, 0}, {0, 0, 1}};
  for (int k = 0; k < 3; ++k) {
    const double a = 2.0 * M_PI * k / 3.0;
    fins.positions.emplace_back(static_cast<float>(std::cos(a)), static_cast<float>(std::sin(a)), 0.5f);
    fins.triangles.emplace_back(0, 2 + k, 1);
  }
  MissingNormals missing;
  missing.auto_smooth_deg = 180.0;
  check_flat(fins, blender_corner_normals(fins, missing));

  // Two triangles of one plane, the second wound the other way: they run along their edge in the
  // same direction, so the edge is sharp (and the plain vertex mean would cancel to nothing).
  TriangleMesh flipped;
  flipped.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  flipped.triangles = {{0, 1, 2}, {1, 2, 3}};
  check_flat(flipped, blender_corner_normals(flipped, missing));
}

TEST_CASE("blender_corner_normals: file vertices join copies split at a seam", "[geom]") {
  // The cube with every corner of every triangle its own vertex, as a reader splits vertices at UV
  // seams; file_vertex names the cube corner each copy came from.
  const TriangleMesh welded = cube();
  TriangleMesh split;
  MissingNormals missing;
  for (const glm::uvec3& t : welded.triangles) {
    const auto first = static_cast<uint32_t>(split.positions.size());
    for (int k = 0; k < 3; ++k) {
      split.positions.push_back(welded.positions[t[k]]);
      missing.file_vertex.push_back(t[k]);
    }
    split.triangles.emplace_back(first, first + 1, first + 2);
  }
  missing.smooth.assign(split.triangle_count(), true);
  check_diagonal(split, blender_corner_normals(split, missing));
  // Without the file's vertices each corner stands alone: flat.
  missing.file_vertex.clear();
  check_flat(split, blender_corner_normals(split, missing));
}

TEST_CASE("blender_corner_normals: degenerate triangles give finite normals and weigh nothing", "[geom]") {
  TriangleMesh mesh = cube();
  // A sliver of zero area at a cube corner, and one whose corners coincide.
  mesh.positions.emplace_back(1, 1, 1);
  mesh.positions.emplace_back(2, 2, 2);
  mesh.triangles.emplace_back(6, 8, 9);
  mesh.triangles.emplace_back(6, 6, 8);
  MissingNormals missing;
  missing.smooth.assign(mesh.triangle_count(), true);
  const std::vector<glm::vec3> corners = blender_corner_normals(mesh, missing);
  for (const glm::vec3& n : corners) {
    CHECK(std::isfinite(n.x));
    CHECK(std::isfinite(n.y));
    CHECK(std::isfinite(n.z));
    CHECK(glm::length(n) == Approx(1.0f).margin(1e-6));
  }
  // The cube's own corner at (1, 1, 1) (corner 1 of triangle 2, the top face) is still the diagonal.
  check_near(corners[3 * 2 + 1], glm::normalize(glm::vec3(1, 1, 1)));
}

TEST_CASE("complete_missing_normals: flat meshes keep no normals, mixed ones split vertices", "[geom]") {
  SECTION("all flat: no normals, no tangents (flat shading)") {
    TriangleMesh mesh = cube();
    complete_missing_normals(mesh, {});
    CHECK(mesh.normals.empty());
    CHECK(mesh.positions.size() == 8);
  }
  SECTION("all smooth: one normal per vertex, no copies") {
    TriangleMesh mesh = cube();
    MissingNormals missing;
    missing.smooth.assign(mesh.triangle_count(), true);
    complete_missing_normals(mesh, missing);
    REQUIRE(mesh.normals.size() == 8);
    for (size_t v = 0; v < 8; ++v) check_near(mesh.normals[v], glm::normalize(mesh.positions[v]));
  }
  SECTION("one smooth face: its corners keep the vertex, flat faces get copies with their face normal") {
    TriangleMesh mesh = cube();
    mesh.uvs.assign(mesh.vertex_count(), glm::vec2(0.25f, 0.5f));
    MissingNormals missing;
    missing.smooth.assign(mesh.triangle_count(), false);
    missing.smooth[2] = missing.smooth[3] = true;
    const TriangleMesh before = mesh;
    complete_missing_normals(mesh, missing);
    REQUIRE(mesh.normals.size() == mesh.positions.size());
    REQUIRE(mesh.uvs.size() == mesh.positions.size());
    for (size_t t = 0; t < mesh.triangle_count(); ++t)
      for (int k = 0; k < 3; ++k) {
        const uint32_t v = mesh.triangles[t][k];
        CHECK(mesh.positions[v] == before.positions[before.triangles[t][k]]);
        CHECK(mesh.uvs[v] == glm::vec2(0.25f, 0.5f));
        check_near(mesh.normals[v], t == 2 || t == 3 ? glm::normalize(mesh.positions[v]) : face_normal(before, t));
      }
    // Each cube corner is met by three faces; one normal each.
    CHECK(mesh.positions.size() == 24);
  }
  SECTION("given normals are kept; missing ones are filled") {
    TriangleMesh mesh = cube();
    mesh.normals.assign(8, glm::vec3(0.0f, 0.0f, 1.0f));
    MissingNormals missing;
    missing.vertex_missing.assign(8, false);
    missing.vertex_missing[0] = true;
    missing.smooth.assign(mesh.triangle_count(), true);
    complete_missing_normals(mesh, missing);
    for (size_t v = 1; v < 8; ++v) CHECK(mesh.normals[v] == glm::vec3(0.0f, 0.0f, 1.0f));
    check_near(mesh.normals[0], glm::normalize(glm::vec3(-1, -1, -1)));
  }
  SECTION("arrays of the wrong size are refused") {
    TriangleMesh mesh = cube();
    MissingNormals missing;
    missing.smooth.assign(3, true);
    CHECK_THROWS_AS(complete_missing_normals(mesh, missing), std::invalid_argument);
    missing.smooth.clear();
    missing.auto_smooth_deg = 0.0;
    CHECK_THROWS_AS(complete_missing_normals(mesh, missing), std::invalid_argument);
  }
}

TEST_CASE("flat_shaded gives every corner its own vertex and face normal", "[geom]") {
  const TriangleMesh mesh = cube();
  const TriangleMesh flat = flat_shaded(mesh);
  REQUIRE(flat.positions.size() == 3 * mesh.triangle_count());
  for (size_t t = 0; t < flat.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k) {
      CHECK(flat.positions[flat.triangles[t][k]] == mesh.positions[mesh.triangles[t][k]]);
      check_near(flat.normals[flat.triangles[t][k]], face_normal(mesh, t));
    }
}

TEST_CASE("vertices_by_position names the first vertex at each position", "[geom]") {
  TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 0, 0}, {-0.0f, 0, 0}, {1, 0, 0}};
  CHECK(vertices_by_position(mesh) == std::vector<uint32_t>{0, 1, 0, 0, 1});
}
