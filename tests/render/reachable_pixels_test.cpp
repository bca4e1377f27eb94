// The pixels whose camera rays cannot meet the scene take their samples without rays: the
// rectangle of pixels that may see it is conservative (checked against exact ray-box tests), and
// a render that skips the others is bit for bit the render that traces them.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "film/camera_rays.h"
#include "film/reachable_pixels.h"
#include "film/pixel_filter.h"
#include "matgeom/builtin/builtin_objects.h"
#include "matrender/asset.h"
#include "matrender/camera.h"
#include "matrender/render.h"
#include "matrender/scene.h"
#include "matrender/texture.h"
#include "test_scenes.h"
#include "uniform_floats.h"

using namespace matrender;

namespace {

// Whether the ray from o along d meets the box [lower, upper] at t > 0 (slab test, in double).
bool ray_meets_box(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& lower, const glm::dvec3& upper) {
  double near = 0.0, far = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a) {
    if (d[a] == 0.0) {
      if (o[a] < lower[a] || o[a] > upper[a]) return false;
      continue;
    }
    double t0 = (lower[a] - o[a]) / d[a], t1 = (upper[a] - o[a]) / d[a];
    if (t0 > t1) std::swap(t0, t1);
    near = std::max(near, t0);
    far = std::min(far, t1);
  }
  return near <= far;
}

// The direction through raster (px, py), in double, as CameraRays::direction builds it.
glm::dvec3 exact_direction(const Camera& camera, double px, double py) {
  const double tan_half = std::tan(0.5 * camera.vertical_fov);
  const double aspect = static_cast<double>(camera.width) / camera.height;
  const double sx = (2.0 * px / camera.width - 1.0) * tan_half * aspect;
  const double sy = (1.0 - 2.0 * py / camera.height) * tan_half;
  const glm::dmat4& m = camera.camera_to_world;
  return glm::normalize(sx * glm::normalize(glm::dvec3(m[0])) + sy * glm::normalize(glm::dvec3(m[1])) -
                        glm::normalize(glm::dvec3(m[2])));
}

// The box around a mesh's vertices.
void grow_box(const matgeom::TriangleMesh& mesh, glm::vec3& lower, glm::vec3& upper) {
  for (const glm::vec3& p : mesh.positions) {
    lower = glm::min(lower, p);
    upper = glm::max(upper, p);
  }
}

// The same mesh with one vertex no triangle uses at `p`: nothing renders differently, but the
// box around its vertices now reaches p.
matgeom::TriangleMesh with_unused_vertex(matgeom::TriangleMesh mesh, const glm::vec3& p) {
  mesh.positions.push_back(p);
  if (!mesh.normals.empty()) mesh.normals.emplace_back(0.0f, 0.0f, 1.0f);
  if (!mesh.uvs.empty()) mesh.uvs.emplace_back(0.0f);
  if (!mesh.tangents.empty()) mesh.tangents.emplace_back(1.0f, 0.0f, 0.0f, 1.0f);
  return mesh;
}

void check_same_floats(const std::vector<float>& a, const std::vector<float>& b, const char* what) {
  INFO(what);
  REQUIRE(a.size() == b.size());
  CHECK(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0);
}

void check_same_frames(const FrameBuffers& a, const FrameBuffers& b) {
  check_same_floats(a.color, b.color, "colour");
  check_same_floats(a.alpha, b.alpha, "alpha");
  check_same_floats(a.depth, b.depth, "depth");
  check_same_floats(a.normal_world, b.normal_world, "world normal");
  check_same_floats(a.normal_camera, b.normal_camera, "camera normal");
  check_same_floats(a.normal_tangent, b.normal_tangent, "tangent-space normal");
  check_same_floats(a.ambient_occlusion, b.ambient_occlusion, "ambient occlusion");
  check_same_floats(a.color_variance, b.color_variance, "colour variance");
  for (const matmaterial::MaterialParameterInfo& info : matmaterial::kMaterialParameters)
    if (a.aovs & parameter_aov(info.id)) check_same_floats(a.parameter(info.id), b.parameter(info.id), "a parameter");
  CHECK(a.label == b.label);
  CHECK(a.part_id == b.part_id);
  CHECK(a.sample_count == b.sample_count);
}

// The textured vase in the middle and a sphere cut by the image's right edge, lit by a lamp and a
// point light; the camera sees them from the side, most of the image empty.
struct TwoObjects {
  matgeom::ObjectAsset vase = matgeom::make_builtin_object("vase", 0);
  matgeom::TriangleMesh sphere = test_scenes::uv_sphere(0.12, 12, {0.0, 0.8, 0.15});
  Camera camera = Camera::look_at({1.6, 0.0, 0.5}, {0.0, 0.15, 0.15}, {0, 0, 1}, 0.6, 56, 40);

  // With `far_vertex` the sphere carries an unused vertex behind the camera, so the box around
  // the vertices contains points behind it and every pixel is traced.
  Scene scene(const Background& background, bool far_vertex) const {
    Scene s;
    add_asset(s, vase);
    Material m = test_scenes::lambert(0.6f);
    const glm::vec3 behind = glm::vec3(camera.camera_to_world[3]) + 3.0f * glm::vec3(camera.camera_to_world[2]);
    s.add_mesh(far_vertex ? with_unused_vertex(sphere, behind) : sphere, {s.add_material(m)});
    RectLamp lamp;
    lamp.light_to_world[3] = glm::dvec4(1.0, 0.5, 1.5, 1.0);
    lamp.power = 150.0;
    s.add_lamp(lamp);
    s.add_lamp(PointLamp{glm::dvec3(0.8, -0.8, 0.8), 40.0, glm::dvec3(1.0)});
    s.set_background(background);
    s.commit();
    return s;
  }

  // The pixels of `camera` whose rays may meet the scene without the far vertex.
  PixelRect pixels_seeing_scene() const {
    glm::vec3 lower(std::numeric_limits<float>::infinity()), upper(-std::numeric_limits<float>::infinity());
    grow_box(vase.mesh, lower, upper);
    grow_box(sphere, lower, upper);
    return pixels_seeing_box(CameraRays(camera), camera.width, camera.height, lower, upper,
                             PixelFilterSampler::kDefaultRadius);
  }
};

TexturePtr gradient_map() {
  std::vector<float> pixels;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 32; ++x) pixels.insert(pixels.end(), {x / 31.0f, y / 15.0f, 0.3f});
  return Texture::from_pixelsf(32, 16, 3, pixels.data(), ColorSpace::NonColor);
}

}  // namespace

TEST_CASE("raster_position is the inverse of a camera ray's direction", "[render]") {
  UniformFloats rng(11);
  for (const Camera& camera : {Camera::look_at({1, -2, 0.5}, {0, 0, 0.2}, {0, 0, 1}, 0.7, 64, 48),
                               Camera::look_at({0, 0, 3}, {0, 0, 0}, {0, 1, 0}, 1.2, 30, 90)}) {
    const CameraRays rays(camera);
    for (int i = 0; i < 200; ++i) {
      const glm::vec2 raster(rng.next() * camera.width, rng.next() * camera.height);
      const float distance = 0.01f + 100.0f * rng.next();
      const glm::vec3 p = rays.origin() + distance * rays.direction(raster.x, raster.y);
      const std::optional<glm::vec2> back = rays.raster_position(p);
      REQUIRE(back);
      CHECK(glm::length(*back - raster) < 1e-3f);
    }
    // Behind the camera and at its centre nothing is in front of it.
    CHECK_FALSE(rays.raster_position(rays.origin() - rays.forward()));
    CHECK_FALSE(rays.raster_position(rays.origin()));
  }
}

TEST_CASE("Every camera ray of a pixel outside pixels_seeing_box misses the box", "[render]") {
  const Camera camera = Camera::look_at({2, -1, 0.7}, {0, 0, 0.2}, {0, 0, 1}, 0.8, 80, 60);
  const CameraRays rays(camera);
  const glm::dvec3 origin(camera.camera_to_world[3]);
  UniformFloats rng(5);
  int outside = 0;
  // Blender's default filter width and a wide one: the pixels left out grow with its reach.
  for (int box = 0; box < 20; ++box) {
    const double radius = box % 2 ? 4.0 : PixelFilterSampler::kDefaultRadius;
    const glm::vec3 centre(rng.next() - 0.5f, rng.next() - 0.5f, rng.next() * 0.5f);
    const glm::vec3 half(0.02f + 0.2f * rng.next(), 0.02f + 0.2f * rng.next(), 0.02f + 0.2f * rng.next());
    const PixelRect rect = pixels_seeing_box(rays, camera.width, camera.height, centre - half, centre + half, radius);
    INFO("box " << box << ": pixels [" << rect.x0 << ", " << rect.x1 << ") x [" << rect.y0 << ", " << rect.y1 << ")");
    CHECK(rect.x0 <= rect.x1);
    CHECK(rect.y0 <= rect.y1);
    // Rays through a grid over each outside pixel's filter support, its corners included.
    constexpr int kGrid = 7;
    for (int y = 0; y < camera.height; ++y)
      for (int x = 0; x < camera.width; ++x) {
        if (rect.contains(x, y)) continue;
        ++outside;
        for (int j = 0; j < kGrid; ++j)
          for (int i = 0; i < kGrid; ++i) {
            const double px = x + 0.5 - radius + 2.0 * radius * i / (kGrid - 1);
            const double py = y + 0.5 - radius + 2.0 * radius * j / (kGrid - 1);
            const bool meets = ray_meets_box(origin, exact_direction(camera, px, py), glm::dvec3(centre - half),
                                             glm::dvec3(centre + half));
            if (meets) FAIL("pixel (" << x << ", " << y << ") is left out but its ray through (" << px << ", " << py
                                      << ") meets the box");
          }
      }
  }
  // The boxes are small: most pixels are left out.
  CHECK(outside > 20 * camera.width * camera.height / 3);
}

TEST_CASE("pixels_seeing_box: an empty box is seen by no pixel, one reaching behind the camera by all", "[render]") {
  const Camera camera = Camera::look_at({2, 0, 0}, {0, 0, 0}, {0, 0, 1}, 0.8, 40, 30);
  const CameraRays rays(camera);
  const glm::vec3 inf(std::numeric_limits<float>::infinity());
  const PixelRect none = pixels_seeing_box(rays, 40, 30, inf, -inf, 1.5);
  CHECK((none.x0 == none.x1 || none.y0 == none.y1));
  const PixelRect all = pixels_seeing_box(rays, 40, 30, {-0.1f, -0.1f, -0.1f}, {3.0f, 0.1f, 0.1f}, 1.5);
  CHECK((all.x0 == 0 && all.y0 == 0 && all.x1 == 40 && all.y1 == 30));
  // A box beside the view (left of it) is seen by no pixel.
  const PixelRect beside = pixels_seeing_box(rays, 40, 30, {0.0f, -5.0f, -0.1f}, {0.1f, -4.0f, 0.1f}, 1.5);
  CHECK((beside.x0 == beside.x1 || beside.y0 == beside.y1));
}

TEST_CASE("Pixels that cannot see the scene render as if their rays were traced, bit for bit", "[render]") {
  const TwoObjects objects;
  const PixelRect seeing = objects.pixels_seeing_scene();
  const int skipped = objects.camera.width * objects.camera.height - (seeing.x1 - seeing.x0) * (seeing.y1 - seeing.y0);
  INFO("pixels that may see the scene: [" << seeing.x0 << ", " << seeing.x1 << ") x [" << seeing.y0 << ", "
                                          << seeing.y1 << ")");
  // The sphere reaches the right edge; a third of the image or more is left out.
  REQUIRE(seeing.x1 == objects.camera.width);
  REQUIRE(skipped > objects.camera.width * objects.camera.height / 3);

  struct Case {
    const char* name;
    Background background;
    bool transparent_background;
    double noise_threshold;
  };
  for (const Case& c : {Case{"uniform background, adaptive sampling", glm::vec3(0.2f, 0.3f, 0.4f), false, 0.05},
                        Case{"transparent background", glm::vec3(0.2f, 0.3f, 0.4f), true, 0.0},
                        Case{"environment map", EnvironmentMap{gradient_map(), 2.0, 0.3}, false, 0.0}}) {
    INFO(c.name);
    RenderSettings settings;
    settings.samples_per_pixel = 24;
    settings.seed = 9;
    settings.threads = 2;
    settings.aovs = all_aovs();
    settings.ambient_occlusion_error = 0.05;
    settings.noise_threshold = c.noise_threshold;
    settings.min_samples = 8;  // checks from the 12th sample on (the automatic minimum, 40, is above 24)
    settings.transparent_background = c.transparent_background;
    Scene skipping = objects.scene(c.background, false);
    Scene tracing = objects.scene(c.background, true);
    FrameBuffers skipped_frame, traced_frame;
    const RenderStats skipped_stats = render(skipping, objects.camera, settings, skipped_frame);
    const RenderStats traced_stats = render(tracing, objects.camera, settings, traced_frame);
    check_same_frames(skipped_frame, traced_frame);
    CHECK(skipped_stats.camera_samples == traced_stats.camera_samples);
    // Exactly the camera rays of the skipped pixels are not traced (they meet nothing, so their
    // paths end there); with adaptive sampling those pixels take fewer samples.
    if (c.noise_threshold == 0.0)
      CHECK(traced_stats.rays - skipped_stats.rays == static_cast<uint64_t>(skipped) * settings.samples_per_pixel);
    else
      CHECK(traced_stats.rays > skipped_stats.rays);
    // Adaptive sampling stopped pixels early: the background's, whose samples all agree, first.
    if (c.noise_threshold > 0.0)
      CHECK(skipped_stats.camera_samples <
            static_cast<uint64_t>(objects.camera.width * objects.camera.height) * settings.samples_per_pixel);
  }
}
