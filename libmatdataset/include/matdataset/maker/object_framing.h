#pragma once
// How make_dataset frames an object, the one rule the planner, the checks and the renderer share:
// the object as its scene describes it, the camera grid about its surface (centre, radius by the
// configuration's rule, ranges) and the views whose camera a floor under it would hide.
#include <cstddef>
#include <vector>

#include "matdataset/maker/dataset_config.h"
#include "matgeom/bounding_sphere.h"
#include "matgeom/camera_grid.h"
#include "matgeom/mesh.h"
#include "matrender/scene_description.h"

namespace matdataset {

// Object `index` as the scene describes it, at UV scale `uv_scale`: its source (a scan's object
// its target parts), its UV pass, and where in the configuration it comes from.
matrender::ObjectDescription dataset_object_description(const DatasetConfig& config, size_t index, double uv_scale);

// How far the cameras are from the grid's centre `centre` by the configuration's radius rule, for
// an object with `mesh` and bounding sphere `bounds` seen in a frame of width / height `aspect`.
double camera_grid_radius(const CameraConfig& camera, const matgeom::TriangleMesh& mesh, const matgeom::Sphere& bounds,
                          const glm::dvec3& centre, double aspect);

struct ObjectFraming {
  matgeom::Sphere bounds;       // the surface's minimal enclosing sphere
  matgeom::CameraGridSpec grid;  // centred on the surface's centroid, sized by the radius rule
};
// The framing of an object of `surface` (world space, as placed).
ObjectFraming object_framing(const DatasetConfig& config, const matgeom::TriangleMesh& surface);

// The grid views (i * n_theta + j, ascending) whose camera is not above the floor object `index`
// stands on (surroundings with a floor, at floor_height), which would see the floor's underside: none without a floor or with the grid above the
// horizon. Reads the object only then. Throws matbase::InputError as the scene builder does for
// an object that cannot be read.
std::vector<size_t> grid_views_under_floor(const DatasetConfig& config, size_t index);

}  // namespace matdataset
