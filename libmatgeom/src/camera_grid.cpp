#include "matgeom/camera_grid.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace matgeom {
namespace {

// Below this length the up vector's component orthogonal to the view direction carries no
// reliable direction: the camera looks (almost) straight along world_up.
constexpr double kParallelTolerance = 1e-12;

bool is_finite(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

void validate_spec(const CameraGridSpec& spec) {
  const auto fail = [](const std::string& problem) {
    throw std::invalid_argument("camera grid: " + problem);
  };
  if (spec.n_phi <= 0 || spec.n_theta <= 0) {
    fail("n_phi and n_theta must be positive (got " + std::to_string(spec.n_phi) + " x " +
         std::to_string(spec.n_theta) + ")");
  }
  if (!(std::isfinite(spec.radius) && spec.radius > 0.0)) {
    fail("the radius must be positive and finite (got " + std::to_string(spec.radius) + ")");
  }
  if (!is_finite(spec.center)) fail("the centre is not finite");
  if (!(std::isfinite(spec.phi_min) && std::isfinite(spec.phi_max) &&
        spec.phi_min <= spec.phi_max)) {
    fail("need finite phi_min <= phi_max (got " + std::to_string(spec.phi_min) + ", " +
         std::to_string(spec.phi_max) + ")");
  }
  if (!(std::isfinite(spec.theta_min) && std::isfinite(spec.theta_max) &&
        spec.theta_min <= spec.theta_max)) {
    fail("need finite theta_min <= theta_max (got " + std::to_string(spec.theta_min) + ", " +
         std::to_string(spec.theta_max) + ")");
  }
}

// Paper, eq. for the cell centres: x_k = x_min + (k + 1/2)(x_max - x_min) / n.
double cell_centre(double lower, double upper, int index, int count) {
  return lower + (index + 0.5) * (upper - lower) / count;
}

// The component of `v` orthogonal to the unit vector `axis`, normalised; zero when `v` is
// (nearly) parallel to `axis`.
glm::dvec3 orthogonal_direction(const glm::dvec3& v, const glm::dvec3& axis) {
  const glm::dvec3 rejected = v - glm::dot(v, axis) * axis;
  const double length = glm::length(rejected);
  return length > kParallelTolerance * glm::length(v) ? rejected / length : glm::dvec3(0.0);
}

GridCamera make_grid_camera(const CameraGridSpec& spec, int i, int j) {
  GridCamera camera;
  camera.i = i;
  camera.j = j;
  camera.phi = cell_centre(spec.phi_min, spec.phi_max, i, spec.n_phi);
  camera.theta = cell_centre(spec.theta_min, spec.theta_max, j, spec.n_theta);
  // Paper: p_ij = c + r [sin phi_i cos theta_j, sin phi_i sin theta_j, cos phi_i].
  const double sin_phi = std::sin(camera.phi);
  camera.position = spec.center + spec.radius * glm::dvec3(sin_phi * std::cos(camera.theta),
                                                           sin_phi * std::sin(camera.theta),
                                                           std::cos(camera.phi));
  camera.camera_to_world = look_at_camera_to_world(camera.position, spec.center);
  return camera;
}

}  // namespace

glm::dmat4 look_at_camera_to_world(const glm::dvec3& eye, const glm::dvec3& target,
                                   const glm::dvec3& world_up) {
  if (!is_finite(eye) || !is_finite(target) || !is_finite(world_up)) {
    throw std::invalid_argument("the position, look-at point or up direction is not finite");
  }
  const glm::dvec3 offset = eye - target;
  // Points 1e-300 apart (whose squared distance underflows) or 1e300 apart (overflows) still give
  // their direction, scaled by the largest component first; at everyday distances the plain
  // quotient keeps every camera exactly as before.
  const double largest = std::max({std::abs(offset.x), std::abs(offset.y), std::abs(offset.z)});
  if (!(largest > 0.0)) throw std::invalid_argument("the position and the look-at point coincide");
  if (!std::isfinite(largest))
    throw std::invalid_argument("the position and the look-at point are too far apart for a direction");
  // The camera looks down its -Z, so +Z points from the target back to the eye.
  const double distance = glm::length(offset);
  const glm::dvec3 backward = std::isnormal(distance) ? offset / distance : glm::normalize(offset / largest);

  // Image up is world_up projected onto the image plane. Looking along world_up leaves it
  // undefined; world +Y and then +X keep the frame a proper rotation.
  glm::dvec3 up = orthogonal_direction(world_up, backward);
  if (up == glm::dvec3(0.0)) up = orthogonal_direction(glm::dvec3(0, 1, 0), backward);
  if (up == glm::dvec3(0.0)) up = orthogonal_direction(glm::dvec3(1, 0, 0), backward);

  // Right-handed: X = Y x Z; recomputing Y = Z x X makes the frame orthonormal to rounding.
  const glm::dvec3 right = glm::normalize(glm::cross(up, backward));
  up = glm::cross(backward, right);

  glm::dmat4 camera_to_world(1.0);
  camera_to_world[0] = glm::dvec4(right, 0.0);
  camera_to_world[1] = glm::dvec4(up, 0.0);
  camera_to_world[2] = glm::dvec4(backward, 0.0);
  camera_to_world[3] = glm::dvec4(eye, 1.0);
  return camera_to_world;
}

GridCamera grid_camera(const CameraGridSpec& spec, int i, int j) {
  validate_spec(spec);
  if (i < 0 || i >= spec.n_phi || j < 0 || j >= spec.n_theta) {
    std::ostringstream problem;
    problem << "camera grid: cell (" << i << ", " << j << ") is outside the " << spec.n_phi << " x "
            << spec.n_theta << " grid";
    throw std::out_of_range(problem.str());
  }
  return make_grid_camera(spec, i, j);
}

std::vector<GridCamera> camera_grid(const CameraGridSpec& spec) {
  validate_spec(spec);
  std::vector<GridCamera> cameras;
  cameras.reserve(static_cast<size_t>(spec.n_phi) * static_cast<size_t>(spec.n_theta));
  for (int i = 0; i < spec.n_phi; ++i) {
    for (int j = 0; j < spec.n_theta; ++j) cameras.push_back(make_grid_camera(spec, i, j));
  }
  return cameras;
}

}  // namespace matgeom
