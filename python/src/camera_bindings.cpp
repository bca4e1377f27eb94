#include "camera_bindings.h"

#include <cmath>
#include <string>
#include <variant>

#include <fmt/format.h>
#include <glm/glm.hpp>
#include <pybind11/numpy.h>

#include "json_text.h"
#include "matbase/input_error.h"
#include "matrender/paper_setup.h"
#include "matrender/scene_file.h"

namespace matpredict_python {
namespace {

namespace py = pybind11;

constexpr const char* kCameraSource = "the camera";
constexpr const char* kGridSource = "the camera grid";

matrender::CameraDescription read_camera_dict(const py::handle& description, const char* source) {
  return matrender::read_camera_text(json_text(description, matbase::DocumentSource(source, matbase::PathStyle::JsonPointer)),
                                     source);
}

py::array_t<double> matrix_array(const glm::dmat3& m) {
  py::array_t<double> array({3, 3});
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) array.mutable_at(r, c) = m[c][r];  // glm is column-major
  return array;
}

py::array_t<double> camera_to_world(const matrender::Camera& camera) {
  py::array_t<double> array({4, 4});
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) array.mutable_at(r, c) = camera.camera_to_world[c][r];
  return array;
}

// OpenCV's K for this camera: its frame x right, y down, z forward (the camera's -Z), pixel
// coordinates with (0, 0) the centre of the top-left pixel. The renderer's ray through raster
// point (px, py), with the image from (0, 0) to (W, H) (camera_rays.h), makes x/z = (px - W/2) / f
// and y/z = (py - H/2) / f for f = (H/2) / tan(fov/2), square pixels; the pixel centres are
// px = u + 1/2, so cx = W/2 - 1/2.
py::array_t<double> intrinsics(const matrender::Camera& camera) {
  const double f = 0.5 * camera.height / std::tan(0.5 * camera.vertical_fov);
  glm::dmat3 k(0.0);
  k[0][0] = f;
  k[1][1] = f;
  k[2][0] = 0.5 * camera.width - 0.5;
  k[2][1] = 0.5 * camera.height - 0.5;
  k[2][2] = 1.0;
  return matrix_array(k);
}

}  // namespace

matrender::Camera camera_from_dict(const LoadedScene& scene, const py::handle& description) {
  return matrender::scene_camera(read_camera_dict(description, kCameraSource), scene.built);
}

py::dict grid_cameras(const LoadedScene& scene, const py::object& grid) {
  py::dict keys = grid.is_none() ? py::dict() : py::dict(grid);
  if (!grid.is_none() && !py::isinstance<py::dict>(grid)) throw py::type_error("grid: expected None or a dict of the grid's keys");
  if (keys.contains("cell")) throw matbase::InputError(std::string(kGridSource) + ": /grid/cell: not taken here: every cell is made");
  keys["cell"] = py::make_tuple(0, 0);
  py::dict description;
  description["grid"] = keys;
  matrender::CameraDescription camera = read_camera_dict(description, kGridSource);
  camera.width = scene.built.camera.width;
  camera.height = scene.built.camera.height;
  camera.vertical_fov = scene.built.camera.vertical_fov;
  auto& cell = std::get<matrender::GridPlacement>(camera.placement);
  py::dict cameras;
  for (cell.i = 0; cell.i < cell.spec.n_phi; ++cell.i)
    for (cell.j = 0; cell.j < cell.spec.n_theta; ++cell.j)
      cameras[py::str(matrender::view_name(cell.i, cell.j))] = py::cast(matrender::scene_camera(camera, scene.built));
  return cameras;
}

matrender::Camera chosen_camera(const LoadedScene& scene, const py::object& camera) {
  if (camera.is_none()) return scene.built.camera;
  if (py::isinstance<matrender::Camera>(camera)) return camera.cast<matrender::Camera>();
  if (py::isinstance<py::dict>(camera)) return camera_from_dict(scene, camera);
  throw py::type_error("camera: expected None (the scene's), a matpredict.Camera or a dict with a scene file camera's keys");
}

void bind_camera(py::module_& module) {
  py::class_<matrender::Camera>(module, "Camera",
                                "A pinhole camera placed in a scene (Scene.camera, Scene.make_camera, Scene.grid_cameras):\n"
                                "Blender's convention, looking down its local -Z with +Y up in the image.")
      .def_readonly("width", &matrender::Camera::width, "Image width in pixels.")
      .def_readonly("height", &matrender::Camera::height, "Image height in pixels.")
      .def_property_readonly("fov_deg", [](const matrender::Camera& c) { return glm::degrees(c.vertical_fov); },
                             "Vertical field of view in degrees.")
      .def_property_readonly("camera_to_world", &camera_to_world,
                             "(4, 4) float64, row-major: columns are the camera's +X (image right), +Y (image up),\n"
                             "+Z (backward, away from what it sees) in world coordinates (metres, Z up) and its position.")
      .def_property_readonly("position", [](const matrender::Camera& c) {
        py::array_t<double> p(3);
        for (int k = 0; k < 3; ++k) p.mutable_at(k) = c.camera_to_world[3][k];
        return p;
      }, "(3,) float64: where the camera is, world coordinates in metres.")
      .def_property_readonly("intrinsics", &intrinsics,
                             "(3, 3) float64 OpenCV K = [[f, 0, cx], [0, f, cy], [0, 0, 1]] in pixels, for OpenCV's\n"
                             "camera frame (x right, y down, z forward: camera_to_world times diag(1, -1, -1, 1))\n"
                             "and pixel coordinates with (0, 0) the centre of the top-left pixel, so that\n"
                             "K @ (x, y, z) / z is the pixel a point projects to; cx = width / 2 - 1/2.")
      .def("__repr__", [](const matrender::Camera& c) {
        const glm::dvec3 p(c.camera_to_world[3]);
        return fmt::format("<matpredict.Camera {}x{} at ({:.4g}, {:.4g}, {:.4g}), {:.4g} deg>", c.width, c.height, p.x, p.y,
                           p.z, glm::degrees(c.vertical_fov));
      });
}

}  // namespace matpredict_python
