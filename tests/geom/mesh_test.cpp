#include "matgeom/mesh.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace {

using Catch::Matchers::StartsWith;

// Unit square in the z = 0 plane, normal +Z, split into two triangles.
matgeom::TriangleMesh unit_square() {
  matgeom::TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  mesh.normals.assign(4, glm::vec3(0, 0, 1));
  mesh.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  mesh.tangents.assign(4, glm::vec4(1, 0, 0, 1));
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

std::string invalid_argument_message(const matgeom::TriangleMesh& mesh, const std::string& what) {
  try {
    matgeom::validate_mesh(mesh, what);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

glm::dvec3 triangle_normal(const matgeom::TriangleMesh& mesh, size_t t) {
  const glm::uvec3 tri = mesh.triangles[t];
  const glm::dvec3 a(mesh.positions[tri[0]]), b(mesh.positions[tri[1]]), c(mesh.positions[tri[2]]);
  return glm::cross(b - a, c - a);
}

}  // namespace

TEST_CASE("part_count counts named and referenced parts", "[geom][render]") {
  matgeom::TriangleMesh mesh;
  CHECK(mesh.part_count() == 0);

  mesh = unit_square();
  CHECK(mesh.part_count() == 1);  // no part ids: everything in part 0

  mesh.triangle_parts = {0, 4};
  CHECK(mesh.part_count() == 5);

  mesh.part_names = {"a", "b", "c", "d", "e", "f", "g"};
  CHECK(mesh.part_count() == 7);

  matgeom::TriangleMesh names_only;
  names_only.part_names = {"a", "b"};
  CHECK(names_only.part_count() == 2);
}

TEST_CASE("validate_mesh accepts consistent meshes", "[geom][render]") {
  CHECK_NOTHROW(matgeom::validate_mesh(matgeom::TriangleMesh{}, "empty"));
  matgeom::TriangleMesh mesh = unit_square();
  CHECK_NOTHROW(matgeom::validate_mesh(mesh, "square"));
  mesh.normals.clear();
  mesh.uvs.clear();
  mesh.tangents.clear();
  mesh.triangle_parts = {0, 1};
  CHECK_NOTHROW(matgeom::validate_mesh(mesh, "square"));
}

TEST_CASE("validate_mesh names the file and the problem", "[geom][render]") {
  matgeom::TriangleMesh mesh = unit_square();

  SECTION("index out of range") {
    mesh.triangles[1] = {0, 2, 900};
    CHECK(invalid_argument_message(mesh, "chair.glb") ==
          "chair.glb: triangle 1 references vertex 900 but the mesh has 4 vertices");
  }
  SECTION("index equal to the vertex count") {
    mesh.triangles[0] = {4, 1, 2};
    CHECK_THAT(invalid_argument_message(mesh, "chair.glb"),
               StartsWith("chair.glb: triangle 0 references vertex 4"));
  }
  SECTION("non-finite position") {
    mesh.positions[2].y = std::numeric_limits<float>::quiet_NaN();
    CHECK_THAT(invalid_argument_message(mesh, "lamp.gltf"), StartsWith("lamp.gltf: vertex 2"));
  }
  SECTION("infinite position") {
    mesh.positions[3].x = std::numeric_limits<float>::infinity();
    CHECK_THAT(invalid_argument_message(mesh, "lamp.gltf"), StartsWith("lamp.gltf: vertex 3"));
  }
  SECTION("normals array of the wrong size") {
    mesh.normals.pop_back();
    CHECK_THAT(invalid_argument_message(mesh, "x.glb"), StartsWith("x.glb: "));
    CHECK(invalid_argument_message(mesh, "x.glb").find("normals") != std::string::npos);
  }
  SECTION("uvs array of the wrong size") {
    mesh.uvs.emplace_back(0, 0);
    CHECK(invalid_argument_message(mesh, "x.glb").find("uvs") != std::string::npos);
  }
  SECTION("tangents array of the wrong size") {
    mesh.tangents.pop_back();
    CHECK(invalid_argument_message(mesh, "x.glb").find("tangents") != std::string::npos);
  }
  SECTION("part ids array of the wrong size") {
    mesh.triangle_parts = {0};
    CHECK(invalid_argument_message(mesh, "x.glb").find("part ids") != std::string::npos);
  }
}

TEST_CASE("transform_mesh maps positions, normals and tangents", "[geom][render]") {
  // Non-uniform scale (2, 1, 1) then translation (1, 2, 3), applied to the plane x + z = 1
  // (normal (1, 0, 1)/sqrt 2). The image is the plane x/2 - 1/2 + z - 3 = 1, i.e.
  // x + 2z = 9, with normal (1, 0, 2)/sqrt 5: the inverse transpose, not the matrix itself.
  matgeom::TriangleMesh mesh;
  mesh.positions = {{1, 0, 0}, {0, 1, 1}, {0, 0, 1}};
  const float s = 1.0f / std::sqrt(2.0f);
  mesh.normals.assign(3, glm::vec3(s, 0, s));
  mesh.tangents.assign(3, glm::vec4(0, 1, 0, -1));
  mesh.triangles = {{0, 1, 2}};

  glm::dmat4 transform(1.0);
  transform[0][0] = 2.0;
  transform[3] = glm::dvec4(1, 2, 3, 1);
  matgeom::transform_mesh(mesh, transform);

  CHECK(mesh.positions[0].x == Approx(3.0));
  CHECK(mesh.positions[0].y == Approx(2.0));
  CHECK(mesh.positions[0].z == Approx(3.0));
  CHECK(mesh.positions[1].x == Approx(1.0));
  CHECK(mesh.positions[1].y == Approx(3.0));
  CHECK(mesh.positions[1].z == Approx(4.0));
  for (const glm::vec3& p : mesh.positions) CHECK(p.x + 2.0f * p.z == Approx(9.0));

  const double inv_sqrt5 = 1.0 / std::sqrt(5.0);
  CHECK(mesh.normals[0].x == Approx(inv_sqrt5));
  CHECK(mesh.normals[0].y == Approx(0.0).margin(1e-7));
  CHECK(mesh.normals[0].z == Approx(2.0 * inv_sqrt5));
  // Tangent (0, 1, 0) is unchanged by the scale; the frame stays right-handed.
  CHECK(mesh.tangents[0].y == Approx(1.0));
  CHECK(mesh.tangents[0].w == -1.0f);
  CHECK(mesh.triangles[0] == glm::uvec3(0, 1, 2));
}

TEST_CASE("transform_mesh keeps outward winding and flips handedness under a mirror",
          "[geom][render]") {
  matgeom::TriangleMesh mesh = unit_square();
  const glm::dvec3 before = triangle_normal(mesh, 0);
  REQUIRE(before.z > 0.0);  // counter-clockwise seen from +Z, the side the normal points to

  // Mirror z -> -z: the outward side becomes -Z.
  glm::dmat4 mirror(1.0);
  mirror[2][2] = -1.0;
  matgeom::transform_mesh(mesh, mirror);

  CHECK(mesh.normals[0].z == Approx(-1.0));
  // The geometric normal from the winding agrees with the shading normal again.
  CHECK(triangle_normal(mesh, 0).z < 0.0);
  CHECK(triangle_normal(mesh, 1).z < 0.0);
  // Tangent +X is unchanged; bitangent = w N x T must still be the image of the old bitangent
  // (0, 1, 0): N x T = (0, 0, -1) x (1, 0, 0) = (0, -1, 0), so w must be -1.
  CHECK(mesh.tangents[0].x == Approx(1.0));
  CHECK(mesh.tangents[0].w == -1.0f);
}

TEST_CASE("transform_mesh rejects a singular transform", "[geom][render]") {
  matgeom::TriangleMesh mesh = unit_square();
  glm::dmat4 flatten(1.0);
  flatten[2][2] = 0.0;
  CHECK_THROWS_AS(matgeom::transform_mesh(mesh, flatten), std::invalid_argument);
}

TEST_CASE("mesh_bounds is the box of the positions", "[geom][render]") {
  matgeom::TriangleMesh mesh;
  const matgeom::Bounds3 empty = matgeom::mesh_bounds(mesh);
  CHECK(empty.lower == glm::dvec3(0.0));
  CHECK(empty.upper == glm::dvec3(0.0));

  mesh.positions = {{1, -2, 3}, {-4, 5, 0.5f}, {2, 0, -6}};
  const matgeom::Bounds3 bounds = matgeom::mesh_bounds(mesh);
  CHECK(bounds.lower == glm::dvec3(-4, -2, -6));
  CHECK(bounds.upper == glm::dvec3(2, 5, 3));
}

TEST_CASE("surface_centroid weights triangles by area", "[geom][render]") {
  // A right triangle with legs 2 (area 2, centroid (2/3, 2/3, 0)) and a right triangle with
  // legs 1 at x = 10 (area 1/2, centroid (10 + 1/3, 1/3, 0)).
  // Area-weighted: (2 (2/3) + 0.5 (31/3)) / 2.5 = 2.6, (2 (2/3) + 0.5 (1/3)) / 2.5 = 0.6.
  // The vertex mean would be x = (0 + 2 + 0 + 10 + 11 + 10)/6 = 5.5.
  matgeom::TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {10, 0, 0}, {11, 0, 0}, {10, 1, 0}};
  mesh.triangles = {{0, 1, 2}, {3, 4, 5}};
  const glm::dvec3 centroid = matgeom::surface_centroid(mesh);
  CHECK(centroid.x == Approx(2.6));
  CHECK(centroid.y == Approx(0.6));
  CHECK(centroid.z == Approx(0.0).margin(1e-12));
}

TEST_CASE("surface_centroid of a closed box far from the origin", "[geom][render]") {
  // A 1 x 2 x 3 box at (1000, 2000, 3000): by symmetry the surface centroid is its centre.
  matgeom::TriangleMesh mesh;
  for (int v = 0; v < 8; ++v) {
    mesh.positions.emplace_back(1000.0f + float(v & 1), 2000.0f + 2.0f * float((v >> 1) & 1),
                                3000.0f + 3.0f * float((v >> 2) & 1));
  }
  mesh.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                    {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  const glm::dvec3 centroid = matgeom::surface_centroid(mesh);
  CHECK(centroid.x == Approx(1000.5).epsilon(1e-12));
  CHECK(centroid.y == Approx(2001.0).epsilon(1e-12));
  CHECK(centroid.z == Approx(3001.5).epsilon(1e-12));
}

TEST_CASE("surface_centroid without surface falls back to the vertex mean", "[geom][render]") {
  matgeom::TriangleMesh mesh;
  CHECK(matgeom::surface_centroid(mesh) == glm::dvec3(0.0));
  mesh.positions = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
  mesh.triangles = {{0, 1, 2}};  // collinear: zero area
  const glm::dvec3 centroid = matgeom::surface_centroid(mesh);
  CHECK(centroid.x == Approx(1.0));
  CHECK(centroid.y == Approx(1.0));
  CHECK(centroid.z == Approx(1.0));
}
