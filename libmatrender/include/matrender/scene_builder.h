#pragma once
// Turning a SceneDescription into what the renderer takes: loads meshes and textures, places the
// objects, assigns materials, makes the lights and the camera, and builds the BVH.
#include <optional>
#include <string>
#include <vector>

#include "matgeom/bounding_sphere.h"
#include "matgeom/light_rig.h"
#include "matrender/camera.h"
#include "matrender/scene.h"
#include "matrender/scene_description.h"

namespace matrender {

struct BuiltScene {
  Scene scene;  // committed
  Camera camera;
  std::vector<uint32_t> object_meshes;   // the scene mesh of each described object, in order
  std::string frame_stem;                // output file prefix: "view_005_016" for grid cell (5, 16), else "view"
  matgeom::Sphere bounds;                // minimal enclosing sphere of all objects
  std::optional<matgeom::LightRig> rig;  // when the paper's rig lights the scene
};

// Throws InputError naming the described item when an input fails to load or does not fit
// (unreadable mesh or texture, unknown part name).
BuiltScene build_scene(const SceneDescription& description);

}  // namespace matrender
