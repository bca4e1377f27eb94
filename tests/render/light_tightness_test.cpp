// No light passes through a surface: a camera inside a closed zero-thickness surface sees exactly
// nothing of lamps outside it, and a lamp inside a closed surface lights nothing outside. Smooth
// shading normals that lean toward a lamp behind the surface, the shadow terminator offset and
// bounces inside must not open a path through it. Exactly 0, not "dark": one leaking sample in
// any pixel fails.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <string>
#include <unistd.h>

#include "matbase/pi.h"
#include "matgeom/io/mesh_io.h"
#include "matgeom/tangents.h"
#include "matrender/asset.h"
#include "matrender/camera.h"
#include "matrender/render.h"
#include "matrender/scene.h"
#include "test_scenes.h"

using namespace matrender;
namespace fs = std::filesystem;

namespace {

using matbase::kPi;

// UV sphere with `segments` meridians and `rings` latitude bands, vertex normals, outward
// counter-clockwise triangles, zero thickness.
matgeom::TriangleMesh uv_sphere(double radius, int segments, int rings) {
  matgeom::TriangleMesh m;
  m.positions.push_back({0.0f, 0.0f, static_cast<float>(radius)});
  for (int r = 1; r < rings; ++r) {
    const double polar = kPi * r / rings;
    for (int s = 0; s < segments; ++s) {
      const double azimuth = 2.0 * kPi * s / segments;
      m.positions.push_back(glm::vec3(glm::dvec3(std::sin(polar) * std::cos(azimuth),
                                                 std::sin(polar) * std::sin(azimuth), std::cos(polar)) *
                                      radius));
    }
  }
  m.positions.push_back({0.0f, 0.0f, static_cast<float>(-radius)});
  const uint32_t south = static_cast<uint32_t>(m.positions.size() - 1);
  auto ring_vertex = [&](int r, int s) { return static_cast<uint32_t>(1 + (r - 1) * segments + s % segments); };
  for (int s = 0; s < segments; ++s) {
    m.triangles.push_back({0, ring_vertex(1, s), ring_vertex(1, s + 1)});
    for (int r = 1; r + 1 < rings; ++r) {
      m.triangles.push_back({ring_vertex(r, s), ring_vertex(r + 1, s), ring_vertex(r + 1, s + 1)});
      m.triangles.push_back({ring_vertex(r, s), ring_vertex(r + 1, s + 1), ring_vertex(r, s + 1)});
    }
    m.triangles.push_back({ring_vertex(rings - 1, s), south, ring_vertex(rings - 1, s + 1)});
  }
  for (const glm::vec3& p : m.positions) m.normals.push_back(glm::normalize(p));
  return m;
}

// Axis-aligned cube of half size h about the origin: 12 outward triangles on 8 corners and no
// normals. With vertex normals averaged over its corners (smoothed_cube) its shading normals lean
// 55 degrees off its faces at the corners.
matgeom::TriangleMesh cube(float h) {
  matgeom::TriangleMesh m;
  for (int i = 0; i < 8; ++i) m.positions.push_back({i & 1 ? h : -h, i & 2 ? h : -h, i & 4 ? h : -h});
  m.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                 {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  return m;
}

// The same cube flat shaded: each face its own four vertices carrying the face normal. Faces
// meet along edges with bit-identical corner positions, so the surface is still closed.
matgeom::TriangleMesh flat_cube(float h) {
  const matgeom::TriangleMesh corners = cube(h);
  matgeom::TriangleMesh m;
  for (const glm::uvec3& t : corners.triangles) {
    const glm::vec3 a = corners.positions[t.x], b = corners.positions[t.y], c = corners.positions[t.z];
    const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
    const uint32_t first = static_cast<uint32_t>(m.positions.size());
    m.positions.insert(m.positions.end(), {a, b, c});
    m.normals.insert(m.normals.end(), {n, n, n});
    m.triangles.push_back({first, first + 1, first + 2});
  }
  return m;
}

// The mesh as a user would bring it: written to an OBJ and read back.
matgeom::ObjectAsset through_obj_file(const matgeom::TriangleMesh& mesh, const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("matrender_tightness_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  matgeom::ObjectAsset asset;
  asset.mesh = mesh;
  asset.mesh.part_names = {"surface"};
  asset.materials = {matmaterial::MaterialInputs("surface")};
  const std::string path = (dir / (name + ".obj")).string();
  matgeom::write_object(asset, path);
  matgeom::ObjectAsset read = matgeom::read_object(path);
  fs::remove_all(dir);
  return read;
}

Material grey_material() {
  Material m;
  m.set(matrender::MaterialParameter::BaseColor, glm::vec3(0.8f));
  m.set(matrender::MaterialParameter::Roughness, 0.5f);
  return m;
}

// An area lamp (square of side `area_size`, 500 W) looking at the origin from `area_at`, a 300 W
// point lamp and a 300 W spot aimed at the origin.
void add_lamps(Scene& scene, double area_size, const glm::dvec3& area_at, const glm::dvec3& point_at, const glm::dvec3& spot_at) {
  RectLamp area;
  const glm::dvec3 back = glm::normalize(area_at);  // the lamp's +Z points away from the origin
  const glm::dvec3 x = glm::normalize(glm::cross(glm::dvec3(0.3, 0.2, 1.0), back));
  area.light_to_world = glm::dmat4(glm::dvec4(x, 0.0), glm::dvec4(glm::cross(back, x), 0.0), glm::dvec4(back, 0.0),
                                   glm::dvec4(area_at, 1.0));
  area.size_x = area.size_y = area_size;
  area.power = 500.0;
  scene.add_lamp(area);
  scene.add_lamp(PointLamp{point_at, 300.0, glm::dvec3(1.0)});
  scene.add_lamp(SpotLamp{spot_at, -spot_at, 1.2, 0.2, 300.0, glm::dvec3(1.0)});
}

struct LeakCount {
  int lit_pixels = 0;
  uint64_t discarded = 0;
};

LeakCount render_and_count(Scene& scene, const Camera& camera, int max_bounces, int spp) {
  RenderSettings settings;
  settings.samples_per_pixel = spp;
  settings.seed = 3;
  settings.max_bounces = settings.max_diffuse_bounces = settings.max_glossy_bounces = max_bounces;
  settings.aovs = 0;
  FrameBuffers frame;
  const RenderStats stats = render(scene, camera, settings, frame);
  LeakCount count;
  for (size_t i = 0; i < frame.color.size(); i += 3)
    if (frame.color[i] != 0.0f || frame.color[i + 1] != 0.0f || frame.color[i + 2] != 0.0f) ++count.lit_pixels;
  count.discarded = stats.discarded_samples;
  return count;
}

// Renders the closed surface with the camera at `eye` inside it and lamps outside, for every
// bounce limit and terminator offset the issue names.
void check_dark_inside(const matgeom::ObjectAsset& closed, const glm::dvec3& eye, const glm::dvec3& look) {
  for (float offset : {0.0f, 0.1f}) {
    Scene scene;
    const uint32_t grey = scene.add_material(grey_material());
    MeshOptions options;
    options.shadow_terminator_geometry_offset = offset;
    add_asset(scene, closed, {grey}, options);
    add_lamps(scene, 0.5, {0.2, -0.4, 0.9}, {0.8, 0.3, 0.2}, {-0.5, 0.6, -0.5});
    const Camera camera = Camera::look_at(eye, look, {0, 0, 1}, kPi / 2, 64, 64);
    for (int bounces : {0, 1, 8}) {
      INFO("terminator offset " << offset << ", max bounces " << bounces);
      const LeakCount leak = render_and_count(scene, camera, bounces, 64);
      CHECK(leak.lit_pixels == 0);
      CHECK(leak.discarded == 0);
    }
  }
}

}  // namespace

TEST_CASE("A camera inside a closed smooth sphere sees no light from lamps outside", "[render]") {
  // The case: radius 0.3 m, 48 x 24 segments, vertex normals, from an OBJ file.
  const matgeom::ObjectAsset sphere = through_obj_file(uv_sphere(0.3, 48, 24), "sphere");
  REQUIRE(!sphere.mesh.normals.empty());
  check_dark_inside(sphere, {0.0, 0.0, 0.0}, {1.0, 0.2, 0.1});
  // Off centre, so most rays meet the wall obliquely and the normals lean far from the facets.
  check_dark_inside(sphere, {0.2, 0.05, -0.1}, {-1.0, 0.3, 0.4});
}

TEST_CASE("A camera inside a closed flat-shaded cube sees no light from lamps outside", "[render]") {
  const matgeom::ObjectAsset flat = through_obj_file(flat_cube(0.3f), "flat_cube");
  REQUIRE(flat.mesh.normals.size() == 36);
  check_dark_inside(flat, {0.0, 0.0, 0.0}, {1.0, 0.2, 0.1});
  check_dark_inside(flat, {0.25, -0.2, 0.1}, {-1.0, 0.6, -0.2});
}

TEST_CASE("A camera inside a cube with corner-averaged normals sees no light from lamps outside", "[render]") {
  matgeom::TriangleMesh corner_averaged = cube(0.3f);
  matgeom::compute_vertex_normals(corner_averaged);
  const matgeom::ObjectAsset smoothed = through_obj_file(corner_averaged, "smoothed_cube");
  REQUIRE(smoothed.mesh.normals.size() == 8);
  check_dark_inside(smoothed, {0.0, 0.0, 0.0}, {1.0, 0.2, 0.1});
  check_dark_inside(smoothed, {0.25, -0.2, 0.1}, {-1.0, 0.6, -0.2});
}

TEST_CASE("Lamps inside a closed surface light nothing outside it", "[render]") {
  for (bool smooth : {false, true}) {
    Scene scene;
    const uint32_t grey = scene.add_material(grey_material());
    const matgeom::ObjectAsset box = through_obj_file(smooth ? uv_sphere(0.3, 48, 24) : flat_cube(0.3f), "box");
    add_asset(scene, box, {grey});
    // A floor under it, where the light would land.
    scene.add_mesh(test_scenes::horizontal_square(4.0, -0.35), {grey});
    add_lamps(scene, 0.1, {0.05, -0.1, 0.15}, {-0.1, 0.05, 0.0}, {0.0, 0.1, 0.1});
    const Camera camera = Camera::look_at({1.2, -1.0, 0.8}, {0, 0, -0.1}, {0, 0, 1}, 0.9, 64, 64);
    for (int bounces : {0, 1, 8}) {
      INFO((smooth ? "smooth sphere" : "flat cube") << ", max bounces " << bounces);
      const LeakCount leak = render_and_count(scene, camera, bounces, 64);
      CHECK(leak.lit_pixels == 0);
      CHECK(leak.discarded == 0);
    }
  }
}
