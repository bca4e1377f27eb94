#pragma once
// matpredict.Camera: a pinhole camera of a scene, its pose and intrinsics as numpy arrays, made
// from a scene file's camera dict or the paper's grid around the scene's objects.
#include <pybind11/pybind11.h>

#include "loaded_scene.h"
#include "matrender/camera.h"

namespace matpredict_python {

void bind_camera(pybind11::module_& module);

// The camera a dict with the scene file's "camera" keys places in `scene` (errors name "the camera").
matrender::Camera camera_from_dict(const LoadedScene& scene, const pybind11::handle& description);
// Every cell of a grid (the scene file's "grid" keys but "cell"; None: the paper's 16 x 32 grid of
// 1 m around the objects' centroid) as {view name: Camera}, row by row, each with the scene
// camera's size and field of view.
pybind11::dict grid_cameras(const LoadedScene& scene, const pybind11::object& grid);
// None: the scene's camera; a matpredict.Camera; or a camera dict.
matrender::Camera chosen_camera(const LoadedScene& scene, const pybind11::object& camera);

}  // namespace matpredict_python
