#pragma once
// The paper's camera grid (section "Camera placement"): a latitude-longitude shell of cameras
// around the object's centroid, each looking down its -Z at the centre with world +Z up.
#include <vector>

#include <glm/glm.hpp>

namespace matgeom {

struct CameraGridSpec {
  glm::dvec3 center{0.0};
  double radius = 1.0;                      // metres
  double phi_min = 0.0;                     // polar angle from +Z, radians
  double phi_max = 1.5707963267948966;      // pi/2
  double theta_min = -1.5707963267948966;   // azimuth, radians
  double theta_max = 1.5707963267948966;
  int n_phi = 16;
  int n_theta = 32;
};

struct GridCamera {
  int i = 0;  // latitude index, 0 .. n_phi-1
  int j = 0;  // longitude index, 0 .. n_theta-1
  double phi = 0.0;
  double theta = 0.0;
  glm::dvec3 position{0.0};
  // Columns: camera +X (image right), +Y (image up), +Z (backward; the camera looks down -Z),
  // translation. Blender's camera convention.
  glm::dmat4 camera_to_world{1.0};
};

// Cell (i, j): phi_i = phi_min + (i + 1/2)(phi_max - phi_min)/n_phi, theta_j likewise,
// p = c + r [sin phi cos theta, sin phi sin theta, cos phi]. Throws std::out_of_range for a
// cell outside the grid and std::invalid_argument for a bad spec.
GridCamera grid_camera(const CameraGridSpec& spec, int i, int j);

// All n_phi x n_theta cameras, i-major (index = i * n_theta + j).
std::vector<GridCamera> camera_grid(const CameraGridSpec& spec);

// Camera-to-world matrix of a camera at `eye` looking at `target`, image +Y toward `world_up`.
// When the view direction is parallel to world_up the image +Y falls back to world +Y
// (or +X), so the matrix is always a proper rotation. Throws std::invalid_argument, with a
// sentence a user can act on, when a vector is not finite or the two points coincide.
glm::dmat4 look_at_camera_to_world(const glm::dvec3& eye, const glm::dvec3& target,
                                   const glm::dvec3& world_up = glm::dvec3(0, 0, 1));

}  // namespace matgeom
