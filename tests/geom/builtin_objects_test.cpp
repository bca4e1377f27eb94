#include "matgeom/builtin_objects.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <stdexcept>
#include <tuple>

#include <catch2/catch.hpp>

using matgeom::ObjectAsset;
using matgeom::TriangleMesh;

namespace {

// Vertex ids after merging vertices at bitwise-equal positions: UV seams duplicate vertices,
// but the surface must still be closed.
std::vector<uint32_t> weld_by_position(const TriangleMesh& mesh) {
  std::map<std::tuple<float, float, float>, uint32_t> ids;
  std::vector<uint32_t> welded(mesh.vertex_count());
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    const glm::vec3& p = mesh.positions[v];
    welded[v] = ids.emplace(std::make_tuple(p.x, p.y, p.z), static_cast<uint32_t>(ids.size()))
                    .first->second;
  }
  return welded;
}

glm::dvec3 corner(const TriangleMesh& mesh, const glm::uvec3& t, int k) {
  return glm::dvec3(mesh.positions[t[k]]);
}

double signed_volume(const TriangleMesh& mesh) {
  double volume = 0.0;
  for (const glm::uvec3& t : mesh.triangles) {
    volume +=
        glm::dot(corner(mesh, t, 0), glm::cross(corner(mesh, t, 1), corner(mesh, t, 2))) / 6.0;
  }
  return volume;
}

}  // namespace

TEST_CASE("builtin object names", "[geom]") {
  CHECK(matgeom::builtin_object_names() == std::vector<std::string>{"vase"});
}

TEST_CASE("the vase is a closed, outward-facing, textured surface", "[geom]") {
  const uint32_t seed = GENERATE(0u, 1u, 42u, 12345u);
  INFO("seed " << seed);
  const ObjectAsset asset = matgeom::make_builtin_object("vase", seed);
  const TriangleMesh& mesh = asset.mesh;
  REQUIRE_NOTHROW(matgeom::validate_mesh(mesh, "vase"));
  CHECK(mesh.triangle_count() > 5000);
  CHECK(mesh.triangle_count() < 7000);
  REQUIRE(mesh.normals.size() == mesh.vertex_count());
  REQUIRE(mesh.uvs.size() == mesh.vertex_count());
  REQUIRE(mesh.tangents.size() == mesh.vertex_count());

  SECTION("watertight: every edge is used once in each direction") {
    const std::vector<uint32_t> welded = weld_by_position(mesh);
    std::map<std::pair<uint32_t, uint32_t>, int> directed_edges;
    for (const glm::uvec3& t : mesh.triangles) {
      const uint32_t a = welded[t[0]], b = welded[t[1]], c = welded[t[2]];
      REQUIRE((a != b && b != c && c != a));
      ++directed_edges[{a, b}];
      ++directed_edges[{b, c}];
      ++directed_edges[{c, a}];
    }
    for (const auto& [edge, count] : directed_edges) {
      INFO("edge " << edge.first << " -> " << edge.second);
      REQUIRE(count == 1);
      REQUIRE(directed_edges.count({edge.second, edge.first}) == 1);
    }
  }

  SECTION("outward: positive volume, vertex normals agree with the faces") {
    const double volume = signed_volume(mesh);
    CHECK(volume > 0.0);
    // A ceramic shell: far less than the solid of revolution it bounds (< pi 0.09^2 0.33).
    CHECK(volume < 0.25 * 3.1416 * 0.09 * 0.09 * 0.33);
    for (const glm::uvec3& t : mesh.triangles) {
      const glm::dvec3 face = glm::normalize(glm::cross(corner(mesh, t, 1) - corner(mesh, t, 0),
                                                        corner(mesh, t, 2) - corner(mesh, t, 0)));
      for (int k = 0; k < 3; ++k) {
        const glm::dvec3 n(mesh.normals[t[k]]);
        CHECK(glm::length(n) == Approx(1.0).margin(1e-5));
        CHECK(glm::dot(n, face) > 0.5);
      }
    }
  }

  SECTION("size: about 0.3 m tall, resting on z = 0") {
    const matgeom::Bounds3 bounds = matgeom::mesh_bounds(mesh);
    CHECK(bounds.lower.z == 0.0);
    CHECK(bounds.upper.z > 0.26);
    CHECK(bounds.upper.z < 0.34);
    const double radius =
        std::max({-bounds.lower.x, bounds.upper.x, -bounds.lower.y, bounds.upper.y});
    CHECK(radius > 0.06);
    CHECK(radius < 0.1);
  }

  SECTION("tangent frames") {
    for (size_t v = 0; v < mesh.vertex_count(); ++v) {
      const glm::vec3 t(mesh.tangents[v]);
      CHECK(glm::length(t) == Approx(1.0).margin(1e-5));
      CHECK(std::abs(glm::dot(t, mesh.normals[v])) < 1e-4);
      CHECK(mesh.tangents[v].w == 1.0f);
    }
  }

  SECTION("parts, materials and images") {
    REQUIRE(mesh.part_names == std::vector<std::string>{"body", "glaze_band"});
    REQUIRE(mesh.triangle_parts.size() == mesh.triangle_count());
    const auto band_triangles =
        std::count(mesh.triangle_parts.begin(), mesh.triangle_parts.end(), 1u);
    CHECK(band_triangles > 0);
    CHECK(band_triangles < static_cast<long>(mesh.triangle_count() / 4));
    REQUIRE(asset.materials.size() == 2);
    const matgeom::MaterialDesc& body = asset.materials[0];
    CHECK(body.metallic == 0.0);
    CHECK(body.normal_strength == 1.0);
    REQUIRE(asset.images.size() == 3);
    for (const matgeom::ImagePixels& image : asset.images) {
      CHECK(image.width == 256);
      CHECK(image.height == 256);
      CHECK(image.channels == 3);
      CHECK(image.data.size() == 256u * 256u * 3u);
    }
    const matgeom::ImagePixels& metallic_roughness =
        asset.images.at(static_cast<size_t>(body.metallic_roughness_image));
    for (size_t i = 0; i < metallic_roughness.data.size(); i += 3) {
      CHECK(metallic_roughness.data[i + 1] >= 51);   // roughness 0.2
      CHECK(metallic_roughness.data[i + 1] <= 128);  // roughness 0.5
      CHECK(metallic_roughness.data[i + 2] == 0);    // metallic
    }
    const matgeom::ImagePixels& normal_map =
        asset.images.at(static_cast<size_t>(body.normal_image));
    double mean_x = 0.0, mean_y = 0.0;
    for (size_t i = 0; i < normal_map.data.size(); i += 3) {
      mean_x += normal_map.data[i];
      mean_y += normal_map.data[i + 1];
      CHECK(normal_map.data[i + 2] > 240);  // subtle bumps: n.z close to 1
    }
    const double texels = 256.0 * 256.0;
    CHECK(mean_x / texels == Approx(127.5).margin(3.0));
    CHECK(mean_y / texels == Approx(127.5).margin(3.0));
  }
}

TEST_CASE("the vase is deterministic for a seed and varies with it", "[geom]") {
  const ObjectAsset a = matgeom::make_builtin_object("vase", 7);
  const ObjectAsset b = matgeom::make_builtin_object("vase", 7);
  const ObjectAsset c = matgeom::make_builtin_object("vase", 8);
  REQUIRE(a.mesh.vertex_count() == b.mesh.vertex_count());
  CHECK(std::memcmp(a.mesh.positions.data(), b.mesh.positions.data(),
                    a.mesh.positions.size() * sizeof(glm::vec3)) == 0);
  CHECK(a.mesh.triangles == b.mesh.triangles);
  CHECK(a.mesh.triangle_parts == b.mesh.triangle_parts);
  CHECK(a.images[0].data == b.images[0].data);
  CHECK(a.materials[1].base_color == b.materials[1].base_color);

  REQUIRE(a.mesh.vertex_count() == c.mesh.vertex_count());
  CHECK(std::memcmp(a.mesh.positions.data(), c.mesh.positions.data(),
                    a.mesh.positions.size() * sizeof(glm::vec3)) != 0);
  CHECK(a.images[0].data != c.images[0].data);
}

TEST_CASE("unknown builtin object names are rejected", "[geom]") {
  CHECK_THROWS_AS(matgeom::make_builtin_object("teapot"), std::invalid_argument);
  CHECK_THROWS_WITH(matgeom::make_builtin_object("teapot"),
                    Catch::Matchers::Contains("teapot") && Catch::Matchers::Contains("vase"));
}
