#include "matgeom/builtin/builtin_objects.h"
#include "matmaterial/material_classes.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <stdexcept>
#include <tuple>

#include <catch2/catch.hpp>

using matgeom::ObjectAsset;
using matgeom::TriangleMesh;
using P = matmaterial::MaterialParameter;

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
  CHECK(matgeom::builtin_object_names() ==
        std::vector<std::string>{"basket", "bed", "book", "bottle", "bowl", "cabinet", "chair", "desk", "lamp", "mug",
                                 "picture_frame", "pillow", "plant_pot", "shelf", "sofa", "stool", "table", "vase"});
}

namespace {

// Height and largest horizontal extent (metres) of each category, from ordinary furniture and
// household items.
struct SizeRange {
  double min_height, max_height, min_width, max_width;
};

const std::map<std::string, SizeRange>& size_ranges() {
  static const std::map<std::string, SizeRange> ranges = {
      {"basket", {0.12, 0.45, 0.25, 0.45}},       {"bed", {0.4, 1.3, 1.9, 2.3}},
      {"book", {0.01, 0.08, 0.12, 0.35}},         {"bottle", {0.18, 0.32, 0.05, 0.09}},
      {"bowl", {0.05, 0.1, 0.13, 0.21}},          {"cabinet", {0.6, 2.1, 0.4, 1.2}},
      {"chair", {0.75, 1.1, 0.4, 0.65}},          {"desk", {0.7, 0.8, 1.0, 1.8}},
      {"lamp", {0.3, 0.7, 0.15, 0.5}},            {"mug", {0.08, 0.12, 0.1, 0.17}},
      {"picture_frame", {0.15, 0.6, 0.1, 0.6}},   {"pillow", {0.08, 0.2, 0.35, 0.7}},
      {"plant_pot", {0.1, 0.25, 0.12, 0.36}},     {"shelf", {0.8, 2.0, 0.6, 1.2}},
      {"sofa", {0.7, 1.0, 1.5, 2.4}},             {"stool", {0.4, 0.8, 0.3, 0.5}},
      {"table", {0.7, 0.8, 0.8, 2.0}},            {"vase", {0.26, 0.34, 0.12, 0.2}},
  };
  return ranges;
}

// Connected components of the welded vertices, as a component id per triangle.
std::vector<uint32_t> triangle_components(const TriangleMesh& mesh, const std::vector<uint32_t>& welded) {
  std::vector<uint32_t> parent(mesh.vertex_count());
  for (uint32_t v = 0; v < parent.size(); ++v) parent[v] = v;
  const auto root = [&](uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const glm::uvec3& t : mesh.triangles) {
    parent[root(welded[t.x])] = root(welded[t.y]);
    parent[root(welded[t.z])] = root(welded[t.y]);
  }
  std::vector<uint32_t> component;
  for (const glm::uvec3& t : mesh.triangles) component.push_back(root(welded[t.x]));
  return component;
}

}  // namespace

TEST_CASE("every built-in object is closed, outward, UV-mapped and of its real size", "[geom]") {
  const std::string name = GENERATE(from_range(matgeom::builtin_object_names()));
  const uint32_t seed = GENERATE(0u, 5u);
  INFO(name << " seed " << seed);
  const ObjectAsset asset = matgeom::make_builtin_object(name, seed);
  const TriangleMesh& mesh = asset.mesh;
  REQUIRE_NOTHROW(matgeom::validate_mesh(mesh, name));
  REQUIRE(mesh.normals.size() == mesh.vertex_count());
  REQUIRE(mesh.uvs.size() == mesh.vertex_count());
  REQUIRE(mesh.tangents.size() == mesh.vertex_count());

  // Named slots, each with a material of the same name and a family label, each used.
  REQUIRE(mesh.part_names.size() == asset.materials.size());
  REQUIRE(mesh.part_count() == mesh.part_names.size());
  for (size_t k = 0; k < asset.materials.size(); ++k) {
    CHECK(asset.materials[k].name == mesh.part_names[k]);
    // A class of the table, never the background.
    CHECK(asset.materials[k].label_id >= 1);
    CHECK(matmaterial::material_class_of_label(asset.materials[k].label_id).has_value());
    const bool used = mesh.triangle_parts.empty() ? k == 0
                                                  : std::count(mesh.triangle_parts.begin(), mesh.triangle_parts.end(),
                                                               static_cast<uint32_t>(k)) > 0;
    CHECK(used);
  }

  // Closed: every welded edge is walked as often in one direction as in the other (pieces may
  // touch, so an edge can be shared by several closed shells).
  const std::vector<uint32_t> welded = weld_by_position(mesh);
  std::map<std::pair<uint32_t, uint32_t>, int> directed_edges;
  for (const glm::uvec3& t : mesh.triangles)
    for (int c = 0; c < 3; ++c) ++directed_edges[{welded[t[c]], welded[t[(c + 1) % 3]]}];
  size_t open_edges = 0;
  for (const auto& [edge, count] : directed_edges) {
    if (edge.first == edge.second) continue;
    const auto opposite = directed_edges.find({edge.second, edge.first});
    if (opposite == directed_edges.end() || opposite->second != count) ++open_edges;
  }
  INFO(open_edges << " of " << directed_edges.size() << " directed edges have no matching opposite");
  CHECK(open_edges == 0);

  // Outward: every closed shell encloses a positive volume; vertex normals agree with faces.
  const std::vector<uint32_t> component = triangle_components(mesh, welded);
  std::map<uint32_t, double> volumes;
  size_t disagreeing = 0, corners = 0;
  for (size_t i = 0; i < mesh.triangle_count(); ++i) {
    const glm::uvec3& t = mesh.triangles[i];
    volumes[component[i]] += glm::dot(corner(mesh, t, 0), glm::cross(corner(mesh, t, 1), corner(mesh, t, 2))) / 6.0;
    const glm::dvec3 face = glm::cross(corner(mesh, t, 1) - corner(mesh, t, 0), corner(mesh, t, 2) - corner(mesh, t, 0));
    if (!(glm::length(face) > 0.0)) continue;
    for (int k = 0; k < 3; ++k, ++corners)
      if (!(glm::dot(glm::dvec3(mesh.normals[t[k]]), face) > 0.0)) ++disagreeing;
  }
  for (const auto& [id, volume] : volumes) {
    INFO("shell " << id << " volume " << volume);
    CHECK(volume > 0.0);
  }
  INFO(disagreeing << " of " << corners << " corners have normals facing away from their face");
  CHECK(disagreeing <= corners / 200);

  // Real size, resting on the floor, centred on the z axis.
  const matgeom::Bounds3 bounds = matgeom::mesh_bounds(mesh);
  const SizeRange range = size_ranges().at(name);
  INFO("bounds (" << bounds.lower.x << ", " << bounds.lower.y << ", " << bounds.lower.z << ") - (" << bounds.upper.x
                  << ", " << bounds.upper.y << ", " << bounds.upper.z << ")");
  CHECK(bounds.lower.z == Approx(0.0).margin(1e-6));
  CHECK(bounds.upper.z >= range.min_height);
  CHECK(bounds.upper.z <= range.max_height);
  const double width = std::max(bounds.upper.x - bounds.lower.x, bounds.upper.y - bounds.lower.y);
  CHECK(width >= range.min_width);
  CHECK(width <= range.max_width);
  CHECK(std::abs(bounds.upper.x + bounds.lower.x) < 0.5 * width);
  CHECK(std::abs(bounds.upper.y + bounds.lower.y) < 0.5 * width);

  for (const glm::vec2& uv : mesh.uvs) {
    CHECK(std::isfinite(uv.x));
    CHECK(std::isfinite(uv.y));
  }
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
    const matmaterial::MaterialInputs& body = asset.materials[0];
    CHECK(body.scalar(P::Metallic) == 0.0);
    CHECK(body.normal_strength == 1.0);
    REQUIRE(asset.images.size() == 3);
    for (const matbase::ImagePixels& image : asset.images) {
      CHECK(image.width == 256);
      CHECK(image.height == 256);
      CHECK(image.channels == 3);
      CHECK(image.data.size() == 256u * 256u * 3u);
    }
    const matbase::ImagePixels& metallic_roughness =
        asset.images.at(static_cast<size_t>(body[P::Roughness].image));
    for (size_t i = 0; i < metallic_roughness.data.size(); i += 3) {
      CHECK(metallic_roughness.data[i + 1] >= 51);   // roughness 0.2
      CHECK(metallic_roughness.data[i + 1] <= 128);  // roughness 0.5
      CHECK(metallic_roughness.data[i + 2] == 0);    // metallic
    }
    const matbase::ImagePixels& normal_map =
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
  CHECK(a.materials[1].color(P::BaseColor) == b.materials[1].color(P::BaseColor));

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
