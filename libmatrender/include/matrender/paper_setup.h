#pragma once
// The MatPredict paper's setup around an object, written once for every tool: the minimal
// enclosing sphere, the light rig normalised to the illuminance the paper aims for, the camera
// grid and its view names, and the scene description of one object under all of it (what
// render_object draws without a scene file).
#include <optional>
#include <string>
#include <vector>

#include "matgeom/bounding_sphere.h"
#include "matgeom/camera_grid.h"
#include "matgeom/light_rig.h"
#include "matgeom/mesh.h"
#include "matrender/camera.h"
#include "matrender/lamp.h"
#include "matrender/scene.h"
#include "matrender/scene_description.h"

namespace matrender {

// The illuminance at the object the paper's rig aims for (section "Lighting rig"). The paper's
// power formula gives about 1e5-1e6 lx at the centre instead; tools normalise to this aim unless
// told to keep the formula's powers.
constexpr double kPaperTargetIlluminanceLux = 1000.0;

// The grid cell every single-view tool uses: (5, 16) of the paper's 16 x 32 grid, about 31
// degrees from the zenith and 3 degrees from +X, a three-quarter view from above.
constexpr int kPaperViewRow = 5;
constexpr int kPaperViewColumn = 16;

// The paper's rig around `bounds` (the minimal enclosing sphere of the objects,
// matgeom::minimal_enclosing_sphere). target_lux: the illuminance at the sphere's centre the
// powers are scaled to; none keeps the formula's powers.
matgeom::LightRig paper_rig(const matgeom::Sphere& bounds, std::optional<double> target_lux = kPaperTargetIlluminanceLux);
// The same around the minimal enclosing sphere of `surface`.
matgeom::LightRig paper_rig(const matgeom::TriangleMesh& surface,
                            std::optional<double> target_lux = kPaperTargetIlluminanceLux);
// The grey-card exposure in stops (light_meter.h) under the rig alone.
double grey_card_exposure(const matgeom::LightRig& rig, const matgeom::CameraGridSpec& grid);
// Adds the rig's lamps to the scene.
void add_rig(Scene& scene, const matgeom::LightRig& rig);

// The camera of grid cell (i, j) of `grid` (its centre, radius and ranges), looking at the
// grid's centre. Throws std::out_of_range for a cell outside the grid.
Camera grid_view(const matgeom::CameraGridSpec& grid, int i, int j, int width, int height,
                 double vertical_fov = Camera{}.vertical_fov);
// Every camera of the grid, row by row (i, then j), with its view name.
struct NamedView {
  std::string name;
  Camera camera;
};
std::vector<NamedView> grid_views(const matgeom::CameraGridSpec& grid, int width, int height,
                                  double vertical_fov = Camera{}.vertical_fov);
// "view_005_016" for cell (5, 16): the stem of every file of that view.
std::string view_name(int i, int j);
// The paper's view of a surface: cell (5, 16) of the paper's grid (1 m) around its surface
// centroid, Blender's default 50 mm lens.
Camera paper_view(const matgeom::TriangleMesh& surface, int width, int height);

// The paper's grid around the surface centroid, at cell (5, 16).
GridPlacement paper_grid_placement();
// One object under the paper's rig (normalised to kPaperTargetIlluminanceLux) seen from the
// paper's grid cell (5, 16), 256 x 256 at 64 samples per pixel.
SceneDescription paper_object_scene(ObjectDescription object);
// render_object's embedded default: the built-in vase, seed 0, under the paper's setup.
SceneDescription default_scene();

}  // namespace matrender
