#include "matgeom/tangents.h"

#include <cmath>
#include <stdexcept>

#include <catch2/catch.hpp>

using matgeom::TriangleMesh;

namespace {

// An n x n grid of quads over [0, 1]^2 in the z = 0 plane, counter-clockwise seen from +z,
// with uv = (x, y) transformed by `uv_of`.
template <typename UvOf>
TriangleMesh grid_plane(int n, UvOf uv_of) {
  TriangleMesh mesh;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const glm::vec2 xy(static_cast<float>(i) / n, static_cast<float>(j) / n);
      mesh.positions.emplace_back(xy, 0.0f);
      mesh.uvs.push_back(uv_of(xy));
    }
  }
  auto index = [n](int i, int j) { return static_cast<uint32_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      mesh.triangles.emplace_back(index(i, j), index(i + 1, j), index(i + 1, j + 1));
      mesh.triangles.emplace_back(index(i, j), index(i + 1, j + 1), index(i, j + 1));
    }
  }
  return mesh;
}

// A bumpy, curved patch with a sheared, non-uniformly scaled UV layout.
TriangleMesh curved_patch() {
  TriangleMesh mesh =
      grid_plane(8, [](glm::vec2 xy) { return glm::vec2(2.0f * xy.x + 0.3f * xy.y, xy.y); });
  for (glm::vec3& p : mesh.positions) {
    p.z = 0.3f * std::sin(3.0f * p.x) * std::cos(2.0f * p.y) + 0.5f * p.x * p.x;
  }
  return mesh;
}

void check_frames(const TriangleMesh& mesh) {
  REQUIRE(mesh.tangents.size() == mesh.vertex_count());
  REQUIRE(mesh.normals.size() == mesh.vertex_count());
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    const glm::vec4& t = mesh.tangents[v];
    const glm::vec3 n = mesh.normals[v];
    INFO("vertex " << v);
    REQUIRE(std::isfinite(t.x));
    REQUIRE(std::isfinite(t.y));
    REQUIRE(std::isfinite(t.z));
    CHECK(glm::length(glm::vec3(t)) == Approx(1.0).margin(1e-5));
    CHECK(std::abs(glm::dot(glm::vec3(t), n)) < 1e-5);
    CHECK(std::abs(t.w) == 1.0f);
  }
}

}  // namespace

TEST_CASE("a plane with uv = xy has tangent +X exactly", "[geom]") {
  TriangleMesh mesh = grid_plane(3, [](glm::vec2 xy) { return xy; });
  matgeom::compute_tangents(mesh);
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    INFO("vertex " << v);
    CHECK(mesh.normals[v] == glm::vec3(0.0f, 0.0f, 1.0f));
    CHECK(mesh.tangents[v] == glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
  }
}

TEST_CASE("tangents are unit length and orthogonal to the normals", "[geom]") {
  TriangleMesh mesh = curved_patch();
  matgeom::compute_tangents(mesh);
  check_frames(mesh);
  for (const glm::vec4& t : mesh.tangents) CHECK(t.w == 1.0f);
  // u grows with x, so every tangent leans towards +x.
  for (const glm::vec4& t : mesh.tangents) CHECK(t.x > 0.5f);
}

TEST_CASE("the bitangent sign follows a mirrored uv layout", "[geom]") {
  SECTION("v mirrored") {
    TriangleMesh mesh = grid_plane(2, [](glm::vec2 xy) { return glm::vec2(xy.x, -xy.y); });
    matgeom::compute_tangents(mesh);
    for (const glm::vec4& t : mesh.tangents) CHECK(t == glm::vec4(1.0f, 0.0f, 0.0f, -1.0f));
    // w N x T must point along +v, which is -y here.
    const glm::vec3 bitangent =
        mesh.tangents[0].w * glm::cross(mesh.normals[0], glm::vec3(mesh.tangents[0]));
    CHECK(bitangent.y == Approx(-1.0));
  }
  SECTION("u mirrored") {
    TriangleMesh mesh = grid_plane(2, [](glm::vec2 xy) { return glm::vec2(-xy.x, xy.y); });
    matgeom::compute_tangents(mesh);
    for (const glm::vec4& t : mesh.tangents) CHECK(t == glm::vec4(-1.0f, 0.0f, 0.0f, -1.0f));
  }
}

TEST_CASE("degenerate uvs give finite orthonormal frames", "[geom]") {
  SECTION("all uvs equal") {
    TriangleMesh mesh = curved_patch();
    for (glm::vec2& uv : mesh.uvs) uv = glm::vec2(0.25f, 0.5f);
    matgeom::compute_tangents(mesh);
    check_frames(mesh);
  }
  SECTION("collinear uvs") {
    TriangleMesh mesh = curved_patch();
    for (size_t v = 0; v < mesh.vertex_count(); ++v) mesh.uvs[v] = glm::vec2(0.1f * v, 0.2f * v);
    matgeom::compute_tangents(mesh);
    check_frames(mesh);
  }
  SECTION("some faces degenerate") {
    TriangleMesh mesh = curved_patch();
    mesh.uvs[0] = mesh.uvs[1];
    mesh.positions[10] = mesh.positions[11];  // zero-area faces too
    matgeom::compute_tangents(mesh);
    check_frames(mesh);
  }
}

TEST_CASE("compute_vertex_normals weights faces by area", "[geom]") {
  TriangleMesh mesh;
  // Vertex 0 is shared by a face of area 2 facing +z and a face of area 0.5 facing +x, and by
  // a zero-area face; vertex 5 is in no face.
  mesh.positions = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 1, 0}, {0, 0, 1}, {5, 5, 5}};
  mesh.triangles = {{0, 1, 2}, {0, 3, 4}, {0, 1, 1}};
  matgeom::compute_vertex_normals(mesh);
  REQUIRE(mesh.normals.size() == 6);
  const glm::vec3 expected = glm::normalize(glm::vec3(0.5f, 0.0f, 2.0f));
  CHECK(mesh.normals[0].x == Approx(expected.x));
  CHECK(mesh.normals[0].y == Approx(0.0).margin(1e-7));
  CHECK(mesh.normals[0].z == Approx(expected.z));
  CHECK(mesh.normals[1] == glm::vec3(0, 0, 1));
  CHECK(mesh.normals[3] == glm::vec3(1, 0, 0));
  CHECK(mesh.normals[5] == glm::vec3(0, 0, 1));
}

TEST_CASE("compute_tangents needs uvs and computes missing normals", "[geom]") {
  TriangleMesh mesh = grid_plane(1, [](glm::vec2 xy) { return xy; });
  mesh.uvs.clear();
  CHECK_THROWS_AS(matgeom::compute_tangents(mesh), std::invalid_argument);

  mesh = grid_plane(1, [](glm::vec2 xy) { return xy; });
  REQUIRE(mesh.normals.empty());
  matgeom::compute_tangents(mesh);
  CHECK(mesh.normals.size() == mesh.vertex_count());
  check_frames(mesh);
}
