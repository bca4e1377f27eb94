// Hard cases never put NaN or Inf into a pixel: degenerate triangles and UVs, zero-length and
// backfacing shading normals, roughness 0 and 1, metallic 1, grazing views, objects from 1 cm to
// 10 m, and lamps touching geometry.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "matbase/pi.h"
#include "matrender/camera.h"
#include "matrender/render.h"
#include "matrender/scene.h"
#include "matrender/scene_limits.h"
#include "test_scenes.h"

using namespace matrender;

namespace {

// A small fan of triangles around the origin with every kind of broken attribute.
matgeom::TriangleMesh broken_mesh(float scale) {
  matgeom::TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0.2f}, {2, 0, 0}, {3, 0, 0}, {-1, 0.5f, 0.5f}};
  for (auto& p : m.positions) p *= scale;
  m.normals = {{0, 0, 1}, {0, 0, 0}, {0, 0, -1}, {1e-30f, 0, 0}, {0, 0, 1}, {0, 0, 1}, {0, -1, 0}};
  m.uvs = {{0, 0}, {0, 0}, {0, 0}, {1e20f, -1e20f}, {0.5f, 0.5f}, {0.5f, 0.5f}, {1, 1}};
  m.triangles = {{0, 1, 2},   // zero-length and opposite normals, degenerate UVs
                 {1, 3, 2},   // denormal normal, huge UVs
                 {1, 4, 5},   // zero-area triangle (collinear)
                 {0, 0, 2},   // repeated vertex
                 {0, 2, 6}};  // normal at right angles to the face
  return m;
}

Material material_with(float roughness, float metallic) {
  Material m;
  m.set(matrender::MaterialParameter::BaseColor, glm::vec3(0.9f, 0.8f, 0.7f));
  m.set(matrender::MaterialParameter::Roughness, roughness);
  m.set(matrender::MaterialParameter::Metallic, metallic);
  // A lacquer as smooth or rough as the base (roughness 0: a mirror coat).
  m.set(matrender::MaterialParameter::Clearcoat, 1.0f);
  m.set(matrender::MaterialParameter::ClearcoatRoughness, roughness);
  // glTF's sheen, as narrow (Sigma 0: Cycles' floor 0.01) or wide as the base is rough.
  m.set(matrender::MaterialParameter::VelvetColor, glm::vec3(0.6f, 0.5f, 0.9f));
  m.set(matrender::MaterialParameter::VelvetSigma, roughness);
  return m;
}

void add_lamps_touching(Scene& scene, float scale) {
  // A rectangle lying in the surface plane and a point lamp exactly on a vertex.
  RectLamp lamp;
  lamp.light_to_world[3] = glm::dvec4(0.5 * scale, 0.5 * scale, 0.0, 1.0);
  lamp.size_x = lamp.size_y = 0.5 * scale;
  lamp.power = 10.0;
  scene.add_lamp(lamp);
  RectLamp above;
  above.light_to_world[3] = glm::dvec4(0.5 * scale, 0.2 * scale, 1.0 * scale, 1.0);
  above.size_x = above.size_y = 0.3 * scale;
  above.power = 10.0 * scale * scale;
  scene.add_lamp(above);
  scene.add_lamp(PointLamp{glm::dvec3(0.0), 10.0, glm::dvec3(1.0)});
  scene.add_lamp(SpotLamp{glm::dvec3(scale, 0.0, 0.0), glm::dvec3(0, 0, -1), 0.5, 0.0, 10.0, glm::dvec3(1.0)});
}

}  // namespace

TEST_CASE("Hard geometry and materials give finite pixels at every scale", "[render]") {
  for (float scale : {0.01f, 1.0f, 10.0f}) {
    for (float roughness : {0.0f, 1.0f}) {
      for (float metallic : {0.0f, 1.0f}) {
        Scene scene;
        scene.add_mesh(broken_mesh(scale), {scene.add_material(material_with(roughness, metallic))});
        scene.add_mesh(test_scenes::horizontal_square(5.0 * scale, -0.01 * scale),
                       {scene.add_material(material_with(roughness, metallic))});
        add_lamps_touching(scene, scale);
        scene.set_background(glm::vec3(0.2f));
        RenderSettings settings;
        settings.samples_per_pixel = 4;
        // A grazing view (2 degrees above the plane) and a view from below.
        for (const glm::dvec3 eye : {glm::dvec3(4.0, 0.3, 0.14), glm::dvec3(0.5, 0.5, -1.0)}) {
          const Camera camera = Camera::look_at(eye * double(scale), glm::dvec3(0.5, 0.3, 0.0) * double(scale),
                                                {0, 0, 1}, 0.9, 24, 24);
          FrameBuffers frame;
          const RenderStats stats = render(scene, camera, settings, frame);
          INFO("scale " << scale << " roughness " << roughness << " metallic " << metallic);
          CHECK(test_scenes::all_finite(frame.color));
          CHECK(test_scenes::all_finite(frame.normal_world));
          CHECK(test_scenes::all_finite(frame.depth));
          CHECK(stats.discarded_samples == 0);
        }
      }
    }
  }
}

TEST_CASE("Grazing views of a smooth normal-mapped sphere stay finite", "[render]") {
  // UV sphere whose shading normals point away from the viewer near the silhouette.
  matgeom::TriangleMesh sphere;
  const int rings = 24, segments = 48;
  for (int i = 0; i <= rings; ++i) {
    for (int j = 0; j <= segments; ++j) {
      const float theta = matbase::kPiAs<float> * i / rings, phi = 2.0f * matbase::kPiAs<float> * j / segments;
      const glm::vec3 n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
      sphere.positions.push_back(n);
      // Bent normals: tilt every normal by 60 degrees so many face away at the silhouette.
      sphere.normals.push_back(glm::normalize(n + glm::vec3(1.7f, 0.0f, 0.0f)));
      sphere.uvs.push_back({float(j) / segments, float(i) / rings});
    }
  }
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const uint32_t a = i * (segments + 1) + j, b = a + segments + 1;
      sphere.triangles.push_back({a, b, a + 1});
      sphere.triangles.push_back({a + 1, b, b + 1});
    }
  Scene scene;
  // The clearcoat and the velvet keep the smooth normal: their lobes are tilted against the
  // normal-mapped frame.
  Material m = material_with(0.05f, 0.5f);
  m.set(matrender::MaterialParameter::ClearcoatRoughness, 0.1f);
  const uint8_t bumpy[4 * 3] = {255, 128, 128, 128, 255, 128, 0, 128, 200, 128, 0, 60};
  m.normal_map = Texture::from_pixels8(2, 2, 3, bumpy, ColorSpace::NonColor);
  scene.add_mesh(sphere, {scene.add_material(m)});
  scene.add_lamp(PointLamp{glm::dvec3(3, 0, 0), 100.0, glm::dvec3(1.0)});
  scene.set_background(glm::vec3(1.0f));
  RenderSettings settings;
  settings.samples_per_pixel = 8;
  for (const bool cycles_parity : {false, true}) {
    settings.cycles_parity = cycles_parity;
    CAPTURE(cycles_parity);
    CHECK(test_scenes::renders_finite(scene, Camera::look_at({0, -4, 0}, {0, 0, 0}, {0, 0, 1}, 0.6, 32, 32), settings));
  }
}

TEST_CASE("What single precision cannot render is refused with the reason, never traced", "[render]") {
  using Catch::Matchers::Contains;
  Scene scene;
  const uint32_t grey = scene.add_material(test_scenes::lambert(0.5f));

  // Geometry beyond the scene limit, or not finite.
  matgeom::TriangleMesh far = test_scenes::horizontal_square(1.0);
  far.positions[2].x = static_cast<float>(2.0 * kMaxSceneCoordinate);
  CHECK_THROWS_WITH(scene.add_mesh(far, {grey}), Contains("mesh 0: vertex 2") && Contains("beyond 65536 m"));
  CHECK(scene.mesh_count() == 0);

  // A mesh of triangles that all have zero area would render nothing: refused. One with area
  // among them is enough.
  matgeom::TriangleMesh zero_area;
  zero_area.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0.5f, 0, 0}};
  zero_area.triangles = {{0, 1, 2}, {0, 0, 3}};
  CHECK_THROWS_WITH(scene.add_mesh(zero_area, {grey}), Contains("mesh 0: every one of its 2 triangles has zero area"));
  zero_area.positions.push_back({0, 1, 0});
  zero_area.triangles.push_back({0, 1, 4});
  const uint32_t mixed = scene.add_mesh(zero_area, {grey});

  // Lamps whose values are each valid but whose emission or size a float cannot hold.
  RectLamp tiny;
  tiny.size_x = 1e-300;
  RectLamp bright;
  bright.power = 1e300;
  RectLamp flat;
  flat.light_to_world[1] = flat.light_to_world[0];  // X and Y axes parallel
  PointLamp far_point;
  far_point.position = glm::dvec3(0.0, 1e7, 0.0);
  PointLamp nan_colour;
  nan_colour.color = glm::dvec3(std::numeric_limits<double>::quiet_NaN());
  SpotLamp no_direction;
  no_direction.direction = glm::dvec3(0.0);
  SpotLamp wide;
  wide.spot_angle = 4.0;
  const std::vector<std::pair<Lamp, const char*>> refused = {
      {tiny, "area"},          {bright, "radiance"},           {flat, "parallel"},       {far_point, "beyond 65536 m"},
      {nan_colour, "colour"},  {no_direction, "direction"},     {wide, "spot angle"}};
  for (const auto& [light, reason] : refused) {
    CAPTURE(reason);
    CHECK_THROWS_WITH(scene.add_lamp(light), Contains("light 0: ") && Contains(reason));
  }
  CHECK(scene.lamps().empty());
  scene.add_lamp(PointLamp{glm::dvec3(0.0, 0.0, 1.0), 10.0, glm::dvec3(1.0)});

  // A camera beyond the limit (Embree asserted on its rays at 1e20 m) or at NaN.
  CHECK(mixed == 0);
  scene.add_mesh(test_scenes::horizontal_square(1.0), {grey});
  RenderSettings settings;
  settings.samples_per_pixel = 1;
  FrameBuffers frame;
  for (const double x : {1e20, 1e5, std::numeric_limits<double>::quiet_NaN()}) {
    CAPTURE(x);
    Camera camera = Camera::look_at({0.0, -1.0, 1.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 0.5, 4, 4);
    camera.camera_to_world[3].x = x;
    CHECK_THROWS_AS(render(scene, camera, settings, frame), std::invalid_argument);
  }
  // Within the limit it renders.
  const Camera near = Camera::look_at({0.0, -1.0, 1.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 0.5, 4, 4);
  CHECK_NOTHROW(render(scene, near, settings, frame));
}
