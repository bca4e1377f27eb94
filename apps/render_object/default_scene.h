#pragma once
// The scenes render_object draws without a scene file: one object (the built-in vase, a glTF file
// given with --mesh or a built-in object given with --object) lit by the paper's light rig and
// seen by one camera of the paper's grid, 256 x 256 at 64 samples per pixel.
#include <string>

#include "scene_description.h"

namespace render_object {

// The illuminance at the object the paper's rig aims for (section "Lighting rig").
constexpr double kPaperTargetIlluminanceLux = 1000.0;

// The paper's 16 x 32 grid on a 1 m shell around the surface centroid, at cell (5, 16): about
// 31 degrees from the zenith and 3 degrees from +X, a three-quarter view from above.
GridPlacement paper_grid_placement();

SceneDescription object_scene(ObjectDescription object);
SceneDescription default_scene();  // the built-in vase, seed 0

ObjectDescription mesh_file_object(const std::string& path);
// "NAME" or "NAME:SEED" as given to --object; throws InputError for an unknown name or bad seed.
ObjectDescription builtin_object(const std::string& argument);

}  // namespace render_object
