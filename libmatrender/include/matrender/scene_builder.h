#pragma once
// Turning a SceneDescription into what the renderer takes: loads meshes and textures, places the
// objects, assigns materials, makes the lights and the camera, and builds the BVH.
#include <atomic>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "matgeom/bounding_sphere.h"
#include "matgeom/light_rig.h"
#include "matrender/camera.h"
#include "matrender/scene.h"
#include "matrender/scene_description.h"
#include "matrender/scene_materials.h"

namespace matrender {

struct BuiltScene {
  Scene scene;  // committed
  Camera camera;
  std::vector<uint32_t> object_meshes;   // the scene mesh of each described object, in order
  std::vector<double> object_uv_scales;  // the scale each object's UV pass ran at (1 where it did not)
  std::string frame_stem;                // output file prefix: "view_005_016" for grid cell (5, 16), else "view"
  matgeom::Sphere bounds;                // minimal enclosing sphere of the objects that are not surroundings
  glm::dvec3 centroid{0.0};              // their surface centroid, where grid cameras look by default
  std::optional<matgeom::LightRig> rig;  // when the paper's rig lights the scene
  // The described materials (those no part uses yet are loaded when first assigned) and each
  // object's surface in world space: what assign_object_materials needs.
  SceneMaterials materials;
  std::vector<matgeom::TriangleMesh> object_surfaces;
  // What the mesh files hold that their readers do not apply (matgeom::ObjectAsset::notes), each
  // "<file>: <note>", once per file: what the tools show before they render.
  std::vector<std::string> notes;
};

// Throws matbase::InputError naming the described item when an input fails to load or does not fit
// (unreadable mesh or texture, unknown part name), and matbase::Cancelled soon after `cancel`
// (when given) is set while materials load (SceneMaterials::cancel_on).
BuiltScene build_scene(const SceneDescription& description, const std::atomic<bool>* cancel = nullptr);

// Object `object`'s surface in world space as build_scene places it, without the UV pass: what
// sizes the things put around it before its scene is built. Throws matbase::InputError as
// build_scene does for an object that cannot be read.
matgeom::TriangleMesh placed_object_surface(const ObjectDescription& object);

// The camera `description` places in the built scene (a grid centred on "centroid" around
// built.centroid). Throws matbase::InputError for a look-at whose up is along its view, a cell
// outside its grid, or a camera beyond single precision's reach (scene_limits.h).
Camera scene_camera(const CameraDescription& description, const BuiltScene& built);

// Puts object `object` (its index in the description) in other materials of the description:
// `materials.material` on every part and `materials.part_materials` by part name, as
// build_scene reads them (the description's source and transform are not used); parts it does
// not name keep the material they have. The BVH is not rebuilt. Throws matbase::InputError for an unknown
// part name or a material input that fails to load, std::out_of_range for an unknown material.
void assign_object_materials(BuiltScene& built, size_t object, const ObjectDescription& materials);

// Environment images by file, each loaded once however many frames light with it.
using EnvironmentImages = std::map<std::string, TexturePtr>;

// The built scene's lamps and world replaced by `lights` (the paper's rig around built.bounds,
// recorded in built.rig) and `background`, the BVH kept. With `images`, an environment's image is
// taken from it, or loaded and kept there. Throws matbase::InputError as build_scene does.
void set_scene_lighting(BuiltScene& built, const LightsDescription& lights, const BackgroundDescription& background,
                        EnvironmentImages* images = nullptr);

}  // namespace matrender
