#include "matgeom/camera_grid.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "matbase/pi.h"

namespace {

using matbase::kPi;

glm::dvec3 column(const glm::dmat4& m, int k) { return glm::dvec3(m[k]); }

void check_near(const glm::dvec3& actual, const glm::dvec3& expected, double tolerance = 1e-12) {
  INFO("actual (" << actual.x << ", " << actual.y << ", " << actual.z << "), expected ("
                  << expected.x << ", " << expected.y << ", " << expected.z << ")");
  CHECK(glm::length(actual - expected) <= tolerance);
}

// Columns 0..2 orthonormal, determinant +1, bottom row (0, 0, 0, 1).
void check_proper_rigid(const glm::dmat4& m) {
  const glm::dvec3 x = column(m, 0), y = column(m, 1), z = column(m, 2);
  CHECK(glm::dot(x, x) == Approx(1.0).epsilon(1e-12));
  CHECK(glm::dot(y, y) == Approx(1.0).epsilon(1e-12));
  CHECK(glm::dot(z, z) == Approx(1.0).epsilon(1e-12));
  CHECK(std::abs(glm::dot(x, y)) < 1e-12);
  CHECK(std::abs(glm::dot(y, z)) < 1e-12);
  CHECK(std::abs(glm::dot(z, x)) < 1e-12);
  CHECK(glm::determinant(glm::dmat3(m)) == Approx(1.0).epsilon(1e-12));
  CHECK(m[0][3] == 0.0);
  CHECK(m[1][3] == 0.0);
  CHECK(m[2][3] == 0.0);
  CHECK(m[3][3] == 1.0);
}

// Every camera of the paper's grid: position by the formula, looking at c, upright.
void check_grid_camera(const matgeom::CameraGridSpec& spec, const matgeom::GridCamera& camera,
                       int i, int j) {
  const double phi = spec.phi_min + (i + 0.5) * (spec.phi_max - spec.phi_min) / double(spec.n_phi);
  const double theta =
      spec.theta_min + (j + 0.5) * (spec.theta_max - spec.theta_min) / double(spec.n_theta);
  CHECK(camera.i == i);
  CHECK(camera.j == j);
  CHECK(camera.phi == Approx(phi).epsilon(1e-14));
  CHECK(camera.theta == Approx(theta).epsilon(1e-14));

  const glm::dvec3 radial(std::sin(phi) * std::cos(theta), std::sin(phi) * std::sin(theta),
                          std::cos(phi));
  const glm::dvec3 expected_position = spec.center + spec.radius * radial;
  const double tolerance = 1e-12 * (spec.radius + glm::length(spec.center));
  check_near(camera.position, expected_position, tolerance);
  check_near(column(camera.camera_to_world, 3), expected_position, tolerance);

  const glm::dmat4& m = camera.camera_to_world;
  check_proper_rigid(m);
  // -Z points at the centre.
  check_near(-column(m, 2), glm::normalize(spec.center - camera.position), 1e-12);
  // Upright: +X horizontal, +Y the projection of world +Z, which in closed form is
  // d(radial)/d(-phi) = (-cos phi cos theta, -cos phi sin theta, sin phi) and +X = d/dtheta
  // normalised = (-sin theta, cos theta, 0).
  CHECK(std::abs(m[0][2]) < 1e-12);
  CHECK(m[1][2] > 0.0);
  check_near(column(m, 0), glm::dvec3(-std::sin(theta), std::cos(theta), 0.0));
  check_near(column(m, 1), glm::dvec3(-std::cos(phi) * std::cos(theta),
                                      -std::cos(phi) * std::sin(theta), std::sin(phi)));
}

}  // namespace

TEST_CASE("default camera grid: 16 x 32 = 512 views on the front hemisphere", "[geom][render]") {
  const matgeom::CameraGridSpec spec;
  CHECK(spec.phi_min == 0.0);
  CHECK(spec.phi_max == Approx(kPi / 2));
  CHECK(spec.theta_min == Approx(-kPi / 2));
  CHECK(spec.theta_max == Approx(kPi / 2));
  CHECK(spec.radius == 1.0);

  const std::vector<matgeom::GridCamera> cameras = matgeom::camera_grid(spec);
  REQUIRE(cameras.size() == 512);
  for (int i = 0; i < 16; ++i) {
    for (int j = 0; j < 32; ++j) {
      const matgeom::GridCamera& camera = cameras[size_t(i) * 32 + size_t(j)];
      check_grid_camera(spec, camera, i, j);
      // Front hemisphere: x >= 0 (theta in [-pi/2, pi/2]) and z >= 0 (phi in [0, pi/2]).
      CHECK(camera.position.x > 0.0);
      CHECK(camera.position.z > 0.0);
    }
  }
  // First and last cells by hand: phi_0 = pi/64, theta_0 = -pi/2 + pi/64.
  CHECK(cameras.front().phi == Approx(kPi / 64));
  CHECK(cameras.front().theta == Approx(-kPi / 2 + kPi / 64));
  CHECK(cameras.back().phi == Approx(kPi / 2 - kPi / 64));
  CHECK(cameras.back().theta == Approx(kPi / 2 - kPi / 64));
}

TEST_CASE("camera grid with an offset centre, radius and sub-range", "[geom][render]") {
  matgeom::CameraGridSpec spec;
  spec.center = glm::dvec3(0.3, -1.2, 0.75);
  spec.radius = 2.5;
  spec.phi_min = 0.2;
  spec.phi_max = 1.1;
  spec.theta_min = 0.5;
  spec.theta_max = 2.9;
  spec.n_phi = 3;
  spec.n_theta = 5;
  const std::vector<matgeom::GridCamera> cameras = matgeom::camera_grid(spec);
  REQUIRE(cameras.size() == 15);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 5; ++j) {
      check_grid_camera(spec, cameras[size_t(i) * 5 + size_t(j)], i, j);
      const matgeom::GridCamera single = matgeom::grid_camera(spec, i, j);
      CHECK(single.camera_to_world == cameras[size_t(i) * 5 + size_t(j)].camera_to_world);
      CHECK(glm::length(single.position - spec.center) == Approx(2.5));
    }
  }
  // Middle cell: phi_1 = 0.2 + 1.5 * 0.3 = 0.65, theta_2 = 0.5 + 2.5 * 0.48 = 1.7.
  CHECK(cameras[1 * 5 + 2].phi == Approx(0.65));
  CHECK(cameras[1 * 5 + 2].theta == Approx(1.7));
}

TEST_CASE("camera grid over a whole sphere stays upright below the equator", "[geom][render]") {
  matgeom::CameraGridSpec spec;
  spec.phi_min = 0.0;
  spec.phi_max = kPi;
  spec.theta_min = -kPi;
  spec.theta_max = kPi;
  spec.n_phi = 7;
  spec.n_theta = 9;
  const std::vector<matgeom::GridCamera> cameras = matgeom::camera_grid(spec);
  REQUIRE(cameras.size() == 63);
  for (const matgeom::GridCamera& camera : cameras) {
    check_grid_camera(spec, camera, camera.i, camera.j);
  }
}

TEST_CASE("a single-point range puts every camera on the formula's position", "[geom][render]") {
  // phi_min = phi_max: the cell centre is that angle for every i.
  matgeom::CameraGridSpec spec;
  spec.phi_min = spec.phi_max = kPi / 3;
  spec.theta_min = spec.theta_max = kPi / 4;
  spec.n_phi = 2;
  spec.n_theta = 1;
  for (const matgeom::GridCamera& camera : matgeom::camera_grid(spec)) {
    check_grid_camera(spec, camera, camera.i, camera.j);
    check_near(camera.position, glm::dvec3(std::sqrt(3.0) / 2 * std::sqrt(0.5),
                                           std::sqrt(3.0) / 2 * std::sqrt(0.5), 0.5));
  }
}

TEST_CASE("looking straight down the Z axis falls back to world +Y up", "[geom][render]") {
  // phi = 0 exactly: the camera sits on the +Z axis above c and looks straight down.
  matgeom::CameraGridSpec spec;
  spec.center = glm::dvec3(1, 2, 3);
  spec.phi_min = spec.phi_max = 0.0;
  spec.n_phi = 1;
  spec.n_theta = 4;
  for (const matgeom::GridCamera& camera : matgeom::camera_grid(spec)) {
    const glm::dmat4& m = camera.camera_to_world;
    check_proper_rigid(m);
    check_near(camera.position, glm::dvec3(1, 2, 4));
    check_near(column(m, 2), glm::dvec3(0, 0, 1));
    check_near(column(m, 1), glm::dvec3(0, 1, 0));
    check_near(column(m, 0), glm::dvec3(1, 0, 0));
  }

  // Straight up from below: still a proper rotation with +Y up in the image.
  const glm::dmat4 up = matgeom::look_at_camera_to_world({0, 0, -2}, {0, 0, 0});
  check_proper_rigid(up);
  check_near(column(up, 2), glm::dvec3(0, 0, -1));
  check_near(column(up, 1), glm::dvec3(0, 1, 0));

  // A world up of +Y looking along Y falls back to +X.
  const glm::dmat4 along_y = matgeom::look_at_camera_to_world({0, 5, 0}, {0, 0, 0}, {0, 1, 0});
  check_proper_rigid(along_y);
  check_near(column(along_y, 1), glm::dvec3(1, 0, 0));
}

TEST_CASE("look_at_camera_to_world for a general direction", "[geom][render]") {
  const glm::dvec3 eye(4, -3, 2), target(1, 1, 0);
  const glm::dmat4 m = matgeom::look_at_camera_to_world(eye, target);
  check_proper_rigid(m);
  check_near(column(m, 3), eye);
  check_near(-column(m, 2), glm::normalize(target - eye));
  CHECK(std::abs(m[0][2]) < 1e-12);
  CHECK(m[1][2] > 0.0);
  // +Y lies in the vertical plane through the view direction.
  CHECK(std::abs(glm::dot(column(m, 1), glm::cross(glm::dvec3(0, 0, 1), eye - target))) < 1e-12);
  CHECK_THROWS_AS(matgeom::look_at_camera_to_world(eye, eye), std::invalid_argument);
}

TEST_CASE("look_at_camera_to_world at distances whose square a double cannot hold", "[geom][render]") {
  // 1e-300 apart: the squared distance underflows to 0, yet the direction is plain +Z.
  const glm::dmat4 near = matgeom::look_at_camera_to_world({1, 0, 0}, {1, 0, 1e-300});
  check_proper_rigid(near);
  check_near(-column(near, 2), glm::dvec3(0, 0, 1));
  // 1e200 away: the square overflows.
  const glm::dmat4 far = matgeom::look_at_camera_to_world({0, 0, 0}, {1e200, 1e200, 0});
  check_near(-column(far, 2), glm::normalize(glm::dvec3(1, 1, 0)));
  // What cannot be aimed is said without the function's name, for the tools to pass on.
  CHECK_THROWS_WITH(matgeom::look_at_camera_to_world({1, 2, 3}, {1, 2, 3}), "the position and the look-at point coincide");
  CHECK_THROWS_WITH(matgeom::look_at_camera_to_world({1e308, 0, 0}, {-1e308, 0, 0}),
                    "the position and the look-at point are too far apart for a direction");
  CHECK_THROWS_WITH(matgeom::look_at_camera_to_world({std::nan(""), 0, 0}, {0, 0, 0}),
                    "the position, look-at point or up direction is not finite");
}

TEST_CASE("camera grid rejects bad specs and cells", "[geom][render]") {
  const matgeom::CameraGridSpec good;
  CHECK_THROWS_AS(matgeom::grid_camera(good, -1, 0), std::out_of_range);
  CHECK_THROWS_AS(matgeom::grid_camera(good, 16, 0), std::out_of_range);
  CHECK_THROWS_AS(matgeom::grid_camera(good, 0, 32), std::out_of_range);
  CHECK_THROWS_AS(matgeom::grid_camera(good, 0, -1), std::out_of_range);
  CHECK_NOTHROW(matgeom::grid_camera(good, 15, 31));

  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  auto bad = [&](auto&& mutate) {
    matgeom::CameraGridSpec spec;
    mutate(spec);
    CHECK_THROWS_AS(matgeom::camera_grid(spec), std::invalid_argument);
    CHECK_THROWS_AS(matgeom::grid_camera(spec, 0, 0), std::invalid_argument);
  };
  bad([](matgeom::CameraGridSpec& s) { s.n_phi = 0; });
  bad([](matgeom::CameraGridSpec& s) { s.n_theta = -3; });
  bad([](matgeom::CameraGridSpec& s) { s.radius = 0.0; });
  bad([](matgeom::CameraGridSpec& s) { s.radius = -1.0; });
  bad([&](matgeom::CameraGridSpec& s) { s.radius = inf; });
  bad([&](matgeom::CameraGridSpec& s) { s.radius = nan; });
  bad([](matgeom::CameraGridSpec& s) {
    s.phi_min = 1.0;
    s.phi_max = 0.5;
  });
  bad([](matgeom::CameraGridSpec& s) {
    s.theta_min = 1.0;
    s.theta_max = -1.0;
  });
  bad([&](matgeom::CameraGridSpec& s) { s.phi_max = nan; });
  bad([&](matgeom::CameraGridSpec& s) { s.theta_min = -inf; });
  bad([&](matgeom::CameraGridSpec& s) { s.center.y = nan; });
}
