#pragma once
// Blender 3.4 as an outside reference: a scene handed to Blender as a JSON description that
// shaders_ref/cycles_render.py rebuilds there, rendered by Cycles into linear EXRs; and Blender's
// own glTF importer (shaders_ref/blender_gltf_import.py). Blender is needed only at run time, and
// only by the optional tests and the bench (docs/conventions.md, "Checked against Blender 3.4.1").
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "matgeom/mesh.h"
#include "matrender/camera.h"
#include "matrender/lamp.h"
#include "matrender/material.h"
#include "matrender/sky.h"

namespace shaders_ref {

// World > Environment Texture from an EXR file, its strength, and a Mapping node's Z rotation.
struct CyclesEnvironment {
  std::string exr_path;
  double strength = 1.0;
  double rotation_z = 0.0;  // radians
};

// Light Paths > Max Bounces; Cycles' defaults.
struct CyclesBounces {
  int total = 12, diffuse = 4, glossy = 4, transmission = 12;
};

enum class CyclesSettings {
  // What would make Cycles' converged image differ from the unbiased integral libmatrender
  // computes is switched off: light clamping and the glossy filter.
  Parity,
  // Cycles' defaults, as a Blender user has them (indirect light clamped at 10, glossy filter 1).
  BlenderDefaults,
};

// What Blender rebuilds: one smooth mesh (vertex normals) in one Principled material (constant
// inputs, and at most a base colour image file on the mesh's UVs), or a glTF file in their place;
// lamps of every kind, a camera and a uniform background or an environment map.
struct CyclesScene {
  matgeom::TriangleMesh mesh;
  matrender::Material material;
  // When not empty, replaces `mesh` and `material`: Blender's own glTF importer makes the objects
  // and their node setups from the file, the way assets reach a Blender user.
  std::string gltf_path;
  // When not empty, replaces `mesh`: an OBJ or PLY file Blender's own importer reads (wm.obj_import,
  // import_mesh.ply, with their defaults), its faces flat or smooth as that importer makes them,
  // every slot in `material`.
  std::string mesh_file_path;
  std::vector<matrender::Lamp> lamps;
  // When set, Blender colours every lamp with its own Blackbody node at this temperature (the
  // lamp's colour white there), while libmatrender renders `lamps` as they are: their colours
  // are then what matrender::blackbody_color makes of the same temperature.
  std::optional<double> lamp_blackbody_kelvin;
  matrender::Camera camera;
  glm::vec3 background{0.0f};
  std::optional<CyclesEnvironment> environment;  // replaces the background
  std::optional<matrender::NishitaSky> sky;       // a Sky Texture (Nishita) instead
  float shadow_terminator_geometry_offset = 0.1f;  // Cycles' default, as matrender::MeshOptions
  CyclesBounces bounces;
  CyclesSettings settings = CyclesSettings::Parity;
};

struct CyclesRender {
  int samples_per_pixel = 16;  // with a noise threshold, Max Samples
  uint32_t seed = 0;
  // Adaptive sampling at this Noise Threshold, with Min Samples 0 (Cycles' automatic); none:
  // every pixel takes samples_per_pixel.
  std::optional<double> noise_threshold;
  std::string exr_path;  // filled by render_with_cycles
  double seconds = 0.0;  // the whole render call: scene sync, BVH, sampling, writing the EXR
};

// True when `blender --version` runs and reports Blender 3.4.
bool cycles_available(const std::string& blender = "blender");

// Writes `folder`/scene.json and runs Blender once for all `renders`, in order, each into
// `folder`/cycles_<spp>_<seed>[_threshold_<threshold>].exr. Throws std::runtime_error naming
// Blender's log on failure.
void render_with_cycles(const CyclesScene& scene, std::vector<CyclesRender>& renders, int threads,
                        const std::string& folder, const std::string& blender = "blender");

// A Mapping node (type Point) in front of an image: uv' = R_z(rotation_z) (scale * uv) + location.
struct BlenderUvMapping {
  std::array<double, 2> location{0.0, 0.0};
  double rotation_z = 0.0;
  std::array<double, 2> scale{1.0, 1.0};
};

// One input of a shader node as Blender's glTF importer left it.
struct BlenderInput {
  std::vector<double> value;  // one number, or RGB
  bool linked = false;        // a node (an image texture, a math node) feeds it
  std::optional<BlenderUvMapping> mapping;  // before the image that feeds it (KHR_texture_transform)
};
// Node name ("Principled BSDF", and "Velvet BSDF" where the importer added one) -> input name -> input.
using BlenderNodes = std::map<std::string, std::map<std::string, BlenderInput>>;
// Material name -> its nodes.
using BlenderMaterials = std::map<std::string, BlenderNodes>;

// Imports `gltf_path` with Blender's glTF importer, working in `folder`. Throws std::runtime_error
// naming Blender's log on failure.
BlenderMaterials import_gltf_with_blender(const std::string& gltf_path, const std::string& folder,
                                          const std::string& blender = "blender");

// What Cycles shows at one UV of a UDIM set of tiles 1001 (red) and 1011 (blue).
struct UdimProbe {
  std::string name;
  glm::vec2 uv;
  glm::vec3 cycles_rgb;
};
// Renders shaders_ref/blender_udim_probe.py's quads; the tiles are left in `folder` as
// probe.<UDIM>.png. Throws std::runtime_error naming Blender's log on failure.
std::vector<UdimProbe> probe_udim_with_blender(const std::string& folder, const std::string& blender = "blender");

// Blender's Sky Texture (Nishita) of `sky` as Cycles shows it as a World, seen by an
// equirectangular camera of width x width / 2 pixels (shaders_ref/blender_sky_probe.py): per pixel,
// row 0 at the top, the direction Cycles looked along and the linear RGB it found there (without
// the Background's strength). Works in `folder`; throws std::runtime_error naming Blender's log.
struct SkyProbe {
  std::vector<glm::dvec3> directions;
  std::vector<glm::dvec3> radiance;
};
SkyProbe probe_sky_with_blender(const matrender::NishitaSky& sky, int width, const std::string& folder,
                                const std::string& blender = "blender");

// Linear RGB of an EXR, row 0 at the top; throws if the size differs.
std::vector<float> read_rgb_exr(const std::string& path, int width, int height);

}  // namespace shaders_ref
