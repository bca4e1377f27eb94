// Direct lighting of a Lambertian plane against closed forms: the rectangle's irradiance from
// Lambert's polygon formula, and spot/point lamps from I a(w) cos / d^2 with Cycles' spot factor;
// and what the camera sees of an area lamp made visible to it.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "matbase/pi.h"
#include "matgeom/camera_grid.h"
#include "matrender/camera.h"
#include "matrender/render.h"
#include "matrender/scene.h"
#include "test_scenes.h"

using namespace matrender;

namespace {

using matbase::kPi;

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

  RectLamp lamp;
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
  scene.add_lamp(lamp);

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
  SpotLamp spot;
  spot.position = glm::dvec3(0.3, 0.2, 1.5);
  spot.direction = glm::normalize(glm::dvec3(0.2, -0.1, -1.0));
  spot.spot_angle = 60.0 * kPi / 180.0;
  spot.blend = 0.4;
  spot.power = 100.0;
  spot.color = glm::dvec3(1.0);
  scene.add_lamp(spot);

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
  PointLamp point;
  point.position = glm::dvec3(-0.4, 0.0, 2.0);
  point.power = 250.0;
  scene.add_lamp(point);
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
  RectLamp lamp;
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
    scene.add_lamp(lamp);
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

namespace {

// Irradiance at x (normal n) by a midpoint rule over a disk of `radius` around `center` whose
// normal is `disk_normal`: E = integral of radiance(q) cos(n, q - x) cos(disk, x - q) / |q - x|^2 dA.
template <class Radiance>
double disk_irradiance(const glm::dvec3& center, const glm::dvec3& disk_normal, double radius, const glm::dvec3& x,
                       const glm::dvec3& n, Radiance&& radiance) {
  const glm::dvec3 a = glm::normalize(glm::cross(disk_normal, std::abs(disk_normal.z) < 0.9 ? glm::dvec3(0, 0, 1)
                                                                                            : glm::dvec3(1, 0, 0)));
  const glm::dvec3 b = glm::cross(disk_normal, a);
  constexpr int kRings = 400, kSectors = 400;
  double sum = 0.0;
  for (int i = 0; i < kRings; ++i)
    for (int j = 0; j < kSectors; ++j) {
      const double r = radius * (i + 0.5) / kRings, phi = 2.0 * kPi * (j + 0.5) / kSectors;
      const glm::dvec3 q = center + r * (std::cos(phi) * a + std::sin(phi) * b);
      const glm::dvec3 to_q = q - x;
      const double d2 = glm::dot(to_q, to_q);
      const glm::dvec3 w = to_q / std::sqrt(d2);
      const double area = r * (radius / kRings) * (2.0 * kPi / kSectors);
      sum += radiance(q) * std::max(0.0, glm::dot(n, w)) * std::abs(glm::dot(disk_normal, w)) / d2 * area;
    }
  return sum;
}

}  // namespace

TEST_CASE("A point lamp of radius R is a disk facing each point: E = P h / (4 pi d (d^2 + R^2))", "[render]") {
  // The disk's radiance P / (4 pi^2 R^2) over its cone, of projected solid angle
  // pi sin^2(alpha) cos(beta) with sin^2(alpha) = R^2 / (d^2 + R^2) and cos(beta) = h / d.
  const float albedo = 0.8f;
  Scene scene;
  scene.add_mesh(test_scenes::horizontal_square(40.0), {scene.add_material(test_scenes::lambert(albedo))});
  PointLamp point;
  point.position = glm::dvec3(0.0, 0.0, 0.5);
  point.power = 50.0;
  point.radius = 0.3;
  scene.add_lamp(point);
  RenderSettings settings;
  settings.samples_per_pixel = 64;
  settings.seed = 3;
  for (const glm::dvec3 target : {glm::dvec3(0.0, 0.0, 0.0), glm::dvec3(0.4, 0.1, 0.0), glm::dvec3(-1.2, 0.9, 0.0)}) {
    const double h = point.position.z, d = glm::length(target - point.position);
    const double expected = albedo / kPi * point.power * h / (4.0 * kPi * d * (d * d + point.radius * point.radius));
    FrameBuffers frame;
    REQUIRE(render(scene, camera_above(target), settings, frame).discarded_samples == 0);
    const auto s = test_scenes::channel_statistics(frame, 0);
    INFO("target " << target.x << "," << target.y << ": " << s.mean << " +- " << s.standard_error << ", expected "
                   << expected << " (a radius-0 lamp: " << albedo / kPi * point.power / (4 * kPi) * h / (d * d * d)
                   << ")");
    CHECK(std::abs(s.mean - expected) < 4.0 * s.standard_error + 1e-4 * expected);
  }
}

TEST_CASE("A spot lamp of radius R weighs each point of its disk by the cone factor toward the lit point", "[render]") {
  const float albedo = 0.5f;
  Scene scene;
  scene.add_mesh(test_scenes::horizontal_square(40.0), {scene.add_material(test_scenes::lambert(albedo))});
  SpotLamp spot;
  spot.position = glm::dvec3(0.2, 0.0, 0.8);
  spot.direction = glm::normalize(glm::dvec3(0.3, 0.0, -1.0));
  spot.spot_angle = 70.0 * kPi / 180.0;
  spot.blend = 0.5;
  spot.power = 80.0;
  spot.radius = 0.25;
  scene.add_lamp(spot);
  const double cos_half = std::cos(0.5 * spot.spot_angle);
  const auto cone_factor = [&](const glm::dvec3& from_lamp) {
    const double cos_t = glm::dot(glm::normalize(from_lamp), spot.direction);
    if (cos_t <= cos_half) return 0.0;
    const double s = glm::clamp((cos_t - cos_half) / ((1.0 - cos_half) * spot.blend), 0.0, 1.0);
    return cos_t * s * s * (3.0 - 2.0 * s);
  };
  RenderSettings settings;
  settings.samples_per_pixel = 64;
  settings.seed = 4;
  // Under the axis, and where the disk's edge straddles the cone's smooth edge.
  for (const glm::dvec3 target : {glm::dvec3(0.44, 0.0, 0.0), glm::dvec3(0.95, 0.2, 0.0)}) {
    const double disk_radiance = spot.power / (4.0 * kPi * kPi * spot.radius * spot.radius);
    const double irradiance = disk_irradiance(spot.position, glm::normalize(target - spot.position), spot.radius,
                                              target, glm::dvec3(0, 0, 1), [&](const glm::dvec3& q) {
                                                return disk_radiance * cone_factor(target - q);
                                              });
    const double expected = albedo / kPi * irradiance;
    FrameBuffers frame;
    REQUIRE(render(scene, camera_above(target), settings, frame).discarded_samples == 0);
    const auto s = test_scenes::channel_statistics(frame, 1);
    INFO("target " << target.x << ": " << s.mean << " +- " << s.standard_error << ", expected " << expected);
    CHECK(std::abs(s.mean - expected) < 4.0 * s.standard_error + 1e-3 * expected);
  }
}

TEST_CASE("A sun gives E = S cos on a plane; with an angle, the mean cosine over its disk of directions", "[render]") {
  const float albedo = 0.7f;
  const glm::dvec3 to_sun = glm::normalize(glm::dvec3(0.5, -0.3, 0.6));
  for (const double angle_deg : {0.0, 12.0}) {
    Scene scene;
    scene.add_mesh(test_scenes::horizontal_square(40.0), {scene.add_material(test_scenes::lambert(albedo))});
    SunLamp sun;
    sun.direction = -to_sun;
    sun.strength = 3.0;
    sun.color = glm::dvec3(1.0, 0.9, 0.8);
    sun.angle = angle_deg * kPi / 180.0;
    scene.add_lamp(sun);
    // A disk of radius tan(angle / 2) at distance 1 toward the sun, of radiance S / (pi r^2 cos^3):
    // the quadrature's cos(disk, x - q) / |q - x|^2 is that cos^3, so E = S / (pi r^2) times the
    // integral of the cosine to the plane over the disk.
    const double r = std::tan(0.5 * sun.angle);
    const double expected_irradiance =
        r == 0.0 ? sun.strength * to_sun.z
                 : disk_irradiance(to_sun, to_sun, r, glm::dvec3(0.0), glm::dvec3(0, 0, 1), [&](const glm::dvec3& q) {
                     const double cos_t = glm::dot(glm::normalize(q), to_sun);
                     return sun.strength / (kPi * r * r * cos_t * cos_t * cos_t);
                   });
    RenderSettings settings;
    settings.samples_per_pixel = 16;
    settings.seed = 9;
    FrameBuffers frame;
    REQUIRE(render(scene, camera_above(glm::dvec3(0.3, 0.2, 0.0)), settings, frame).discarded_samples == 0);
    for (int c = 0; c < 3; ++c) {
      const double expected = albedo / kPi * expected_irradiance * sun.color[c];
      const auto s = test_scenes::channel_statistics(frame, c);
      INFO("angle " << angle_deg << " channel " << c << ": " << s.mean << " +- " << s.standard_error << ", expected "
                    << expected);
      CHECK(std::abs(s.mean - expected) < 4.0 * s.standard_error + 1e-4 * expected);
    }
  }
}

TEST_CASE("Camera rays do not see a sun, a mirror shows it with radiance S / (pi r^2 cos^3)", "[render]") {
  SunLamp sun;
  sun.direction = glm::dvec3(0, 0, -1);
  sun.strength = 2.0;
  sun.angle = 20.0 * kPi / 180.0;
  RenderSettings settings;
  settings.samples_per_pixel = 4;
  settings.aovs = 0;
  {
    Scene empty;
    empty.add_lamp(sun);
    FrameBuffers frame;
    render(empty, Camera::look_at({0, 0, 0}, {0, 0, 1}, {0, 1, 0}, 0.01, 4, 4), settings, frame);
    for (const float v : frame.color) CHECK(v == 0.0f);
  }
  // A perfect mirror (metallic 1, roughness 0, base colour 1: F = 1) seen straight from above
  // reflects the centre of the sun's disk.
  Scene scene;
  Material mirror;
  mirror.set(MaterialParameter::BaseColor, glm::vec3(1.0f));
  mirror.set(MaterialParameter::Metallic, 1.0f);
  mirror.set(MaterialParameter::Roughness, 0.0f);
  scene.add_mesh(test_scenes::horizontal_square(40.0), {scene.add_material(mirror)});
  scene.add_lamp(sun);
  FrameBuffers frame;
  render(scene, camera_above(glm::dvec3(0.0)), settings, frame);
  const double r = std::tan(0.5 * sun.angle);
  CHECK(test_scenes::channel_statistics(frame, 0).mean == Approx(sun.strength / (kPi * r * r)).epsilon(1e-4));
}
