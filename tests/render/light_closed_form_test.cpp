// Direct lighting of a Lambertian plane against closed forms: the rectangle's irradiance from
// Lambert's polygon formula, and spot/point lamps from I a(w) cos / d^2 with Cycles' spot factor;
// and what the camera sees of an area lamp made visible to it.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "matgeom/camera_grid.h"
#include "matrender/camera.h"
#include "matrender/render.h"
#include "matrender/scene.h"
#include "test_scenes.h"

using namespace matrender;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Irradiance at x (normal n) from a uniform Lambertian polygon of radiance L (Lambert 1760;
// e.g. Arvo 1995, eq. 9): E = L/2 sum_i angle(v_i, v_i+1) n . unit(v_i x v_i+1), vertices
// relative to x, taken in the order that makes the sum positive.
double polygon_irradiance(const std::vector<glm::dvec3>& corners, const glm::dvec3& x, const glm::dvec3& n,
                          double radiance) {
  double sum = 0.0;
  for (size_t i = 0; i < corners.size(); ++i) {
    const glm::dvec3 a = glm::normalize(corners[i] - x);
    const glm::dvec3 b = glm::normalize(corners[(i + 1) % corners.size()] - x);
    const double angle = std::acos(glm::clamp(glm::dot(a, b), -1.0, 1.0));
    sum += angle * glm::dot(n, glm::normalize(glm::cross(a, b)));
  }
  return 0.5 * radiance * std::abs(sum);
}

// A camera 1 m above `target`, looking straight down with a field of view so narrow that the
// irradiance is constant over the image.
Camera camera_above(const glm::dvec3& target) {
  return Camera::look_at(target + glm::dvec3(0, 0, 1), target, glm::dvec3(0, 1, 0), 0.002, 16, 16);
}

}  // namespace

TEST_CASE("A Lambertian plane under a rectangular lamp matches the polygon irradiance", "[render]") {
  const float albedo = 0.6f;
  Scene scene;
  scene.add_mesh(test_scenes::horizontal_square(40.0), {scene.add_material(test_scenes::lambert(albedo))});

  RectLight lamp;
  const glm::dvec3 centre(0.1, -0.2, 0.8);
  // Tilted lamp: +X along (1, 0, 0.3), emitting down its -Z toward the plane.
  const glm::dvec3 ex = glm::normalize(glm::dvec3(1, 0, 0.3));
  const glm::dvec3 ey(0, 1, 0);
  const glm::dvec3 ez = glm::cross(ex, ey);
  lamp.light_to_world = glm::dmat4(glm::dvec4(ex, 0), glm::dvec4(ey, 0), glm::dvec4(ez, 0), glm::dvec4(centre, 1));
  lamp.size_x = 0.5;
  lamp.size_y = 0.3;
  lamp.power = 40.0;
  lamp.color = glm::dvec3(1.0, 0.5, 0.25);
  scene.add_light(lamp);

  const double radiance = lamp.power / (4.0 * lamp.size_x * lamp.size_y);  // Cycles: P / (4 a b)
  const std::vector<glm::dvec3> corners = {
      centre - 0.25 * ex - 0.15 * ey, centre + 0.25 * ex - 0.15 * ey, centre + 0.25 * ex + 0.15 * ey,
      centre - 0.25 * ex + 0.15 * ey};

  RenderSettings settings;
  settings.samples_per_pixel = 64;
  settings.seed = 7;
  for (const glm::dvec3 target : {glm::dvec3(0.1, -0.2, 0), glm::dvec3(0.9, 0.5, 0), glm::dvec3(-1.5, 0.3, 0)}) {
    const double irradiance = polygon_irradiance(corners, target, glm::dvec3(0, 0, 1), radiance);
    FrameBuffers frame;
    const RenderStats stats = render(scene, camera_above(target), settings, frame);
    REQUIRE(stats.discarded_samples == 0);
    for (int c = 0; c < 3; ++c) {
      const double expected = albedo / kPi * irradiance * lamp.color[c];
      const auto s = test_scenes::channel_statistics(frame, c);
      INFO("target " << target.x << "," << target.y << " channel " << c << " mean " << s.mean << " expected "
                     << expected << " standard error " << s.standard_error);
      CHECK(std::abs(s.mean - expected) < 4.0 * s.standard_error + 1e-4 * expected);
    }
  }
}

TEST_CASE("A Lambertian plane under a spot lamp gets I a(w) cos / d^2", "[render]") {
  const float albedo = 0.5f;
  Scene scene;
  scene.add_mesh(test_scenes::horizontal_square(40.0), {scene.add_material(test_scenes::lambert(albedo))});
  SpotLight spot;
  spot.position = glm::dvec3(0.3, 0.2, 1.5);
  spot.direction = glm::normalize(glm::dvec3(0.2, -0.1, -1.0));
  spot.spot_angle = 60.0 * kPi / 180.0;
  spot.blend = 0.4;
  spot.power = 100.0;
  spot.color = glm::dvec3(1.0);
  scene.add_light(spot);

  RenderSettings settings;
  settings.samples_per_pixel = 4;
  const double cos_half = std::cos(0.5 * spot.spot_angle);
  int inside_smooth_edge = 0;
  for (double x = -0.6; x <= 1.2; x += 0.15) {
    const glm::dvec3 target(x, 0.1, 0.0);
    const glm::dvec3 to_point = target - spot.position;
    const double d = glm::length(to_point);
    const double cos_t = glm::dot(to_point / d, spot.direction);
    // Cycles' spot factor written out: cos t * smoothstep over the blend band, 0 outside the cone.
    double factor = 0.0;
    if (cos_t > cos_half) {
      const double s = glm::clamp((cos_t - cos_half) / ((1.0 - cos_half) * spot.blend), 0.0, 1.0);
      factor = cos_t * s * s * (3.0 - 2.0 * s);
      if (s < 1.0) ++inside_smooth_edge;
    }
    const double cos_surface = -to_point.z / d;
    const double expected = albedo / kPi * spot.power / (4.0 * kPi) * factor * cos_surface / (d * d);
    FrameBuffers frame;
    render(scene, camera_above(target), settings, frame);
    const auto s = test_scenes::channel_statistics(frame, 1);
    INFO("x " << x << " mean " << s.mean << " expected " << expected);
    CHECK(std::abs(s.mean - expected) <= 2e-3 * expected + 1e-7);
  }
  CHECK(inside_smooth_edge > 0);  // the sweep crosses the blend band
}

TEST_CASE("A point lamp's intensity is P / (4 pi) per steradian", "[render]") {
  const float albedo = 0.8f;
  Scene scene;
  scene.add_mesh(test_scenes::horizontal_square(40.0), {scene.add_material(test_scenes::lambert(albedo))});
  PointLight point;
  point.position = glm::dvec3(-0.4, 0.0, 2.0);
  point.power = 250.0;
  scene.add_light(point);
  const glm::dvec3 target(0.5, 0.25, 0.0);
  const glm::dvec3 to_point = target - point.position;
  const double d = glm::length(to_point);
  const double expected = albedo / kPi * point.power / (4.0 * kPi) * (-to_point.z / d) / (d * d);
  RenderSettings settings;
  settings.samples_per_pixel = 4;
  FrameBuffers frame;
  render(scene, camera_above(target), settings, frame);
  CHECK(test_scenes::channel_statistics(frame, 0).mean == Approx(expected).epsilon(2e-3));
}

TEST_CASE("An area lamp visible to the camera shows its radiance P / (4 a b), only then and only its front", "[render]") {
  // Nothing but the lamp in the scene, facing the camera (lamps emit down their -Z), filling the
  // view: every sample meets it, and camera rays take its radiance whole.
  RectLight lamp;
  lamp.light_to_world = matgeom::look_at_camera_to_world({0.0, 0.0, 1.0}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0});
  lamp.size_x = 2.0;
  lamp.size_y = 1.0;
  lamp.power = 40.0;
  lamp.color = glm::dvec3(1.0, 0.5, 0.25);
  const double radiance = lamp.power / (4.0 * lamp.size_x * lamp.size_y);
  struct View {
    bool visible;
    glm::dvec3 eye;
    double expected;  // times the colour
  };
  for (const View view : {View{true, {0.0, 0.0, 0.0}, radiance}, View{false, {0.0, 0.0, 0.0}, 0.0},
                          View{true, {0.0, 0.0, 2.0}, 0.0}}) {  // from behind: its back emits nothing
    lamp.visible_to_camera = view.visible;
    Scene scene;
    scene.add_light(lamp);
    RenderSettings settings;
    settings.samples_per_pixel = 4;
    settings.aovs = 0;
    FrameBuffers frame;
    render(scene, Camera::look_at(view.eye, {0.0, 0.0, 1.0}, {0, 1, 0}, 0.2, 6, 6), settings, frame);
    CAPTURE(view.visible, view.eye.z);
    for (size_t i = 0; i < frame.color.size(); ++i)
      CHECK(frame.color[i] == Approx(view.expected * lamp.color[static_cast<int>(i % 3)]).epsilon(1e-6).margin(1e-9));
  }
}
