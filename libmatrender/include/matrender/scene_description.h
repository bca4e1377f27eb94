#pragma once
// A scene as plain data, the model every tool shares: read from a scene file (scene_file.h) or
// made for an object under the paper's rig and camera (paper_setup.h), adjusted by a tool's
// options, then built into a Scene (scene_builder.h). Describing first lets every input be
// checked before anything is loaded or rendered, so a bad input never writes a file.
#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

#include "matbase/input_error.h"
#include "matgeom/camera_grid.h"
#include "matgeom/io/mesh_io.h"
#include "matgeom/object_asset.h"
#include "matgeom/room.h"
#include "matmaterial/library/material_library.h"
#include "matrender/camera.h"
#include "matrender/lamp.h"
#include "matrender/material.h"
#include "matrender/render.h"
#include "matrender/sky.h"
#include "matrender/texture.h"

namespace matrender {

// Where a described item came from, so that problems found only while building (a corrupt mesh,
// an unknown part name) still point at the value to fix.
struct Origin {
  std::string source;                  // scene file path, or the command-line option
  std::optional<std::string> pointer;  // JSON pointer (RFC 6901) into the scene file; none for an option

  // "scene.json: /objects/1/mesh" for child "/mesh" of "/objects/1"; just "--mesh" for an option.
  std::string describe(const std::string& child = "") const;
  matbase::InputError error(const std::string& child, const std::string& message) const;
};

// A texture file to load; the path is already resolved against the scene file's folder.
struct TextureFile {
  std::string path;
  ColorSpace color_space = ColorSpace::NonColor;
  TextureWrap wrap = TextureWrap::Repeat;
  Origin origin;
};

// A material folder (matmaterial/folder/material_folder.h: MatSynth's layout) to read; the path is already
// resolved against the scene file's folder.
struct MaterialFolderFile {
  std::string path;
  Origin origin;
};

// A material of the procedural library (matmaterial/library/material_library.h), generated when first used.
struct LibraryMaterialRequest {
  matmaterial::LibraryMaterialSpec spec;
  int resolution = kDefaultLibraryResolution;
  Origin origin;
  static constexpr int kDefaultLibraryResolution = 1024;
};

struct MaterialDescription {
  // Every constant (factors, channels, strengths, label, model); the texture pointers stay empty
  // until the files below are loaded.
  Material constants;
  // The texture file of each parameter that has one, by matmaterial::MaterialParameter.
  std::array<std::optional<TextureFile>, matmaterial::kMaterialParameterCount> textures;
  std::optional<TextureFile> normal_map;
  // When one is set, the material is the folder's, read when first used, or the library's,
  // generated then: the fields above are unused, except a label_id the description gives, which
  // replaces the class's.
  std::optional<MaterialFolderFile> folder;
  std::optional<LibraryMaterialRequest> library;
  std::optional<int> label_id;
};

struct MeshFile {
  std::string path;  // .glb, .gltf, .ply or .obj
  matgeom::ObjectReadOptions read_options;  // the scene file's "auto_smooth_deg"
  // The file's parts (by name) that make the object: only `only_parts`, or every part but
  // `except_parts` (a scan's object and the room around it, from one file); neither: every part.
  std::vector<std::string> only_parts;
  std::vector<std::string> except_parts;
};
struct BuiltinObject {
  std::string name;
  uint32_t seed = 0;
};
// An object handed over in memory, already checked (the Python package's meshes from arrays).
struct GivenObject {
  std::shared_ptr<const matgeom::ObjectAsset> asset;
};
// A floor, walls and a ceiling made to measure (matgeom/room.h), its parts "floor", "walls" and
// "ceiling" in the scene's default material unless the description assigns them others.
struct RoomObject {
  matgeom::RoomSpec spec;
};

// When an object's mesh gets new UVs from the paper's UV pass (matgeom/uv/uv_pass.h) before it is
// placed: never, only when the mesh has no UVs of its own, or always.
enum class UvPassMode { Never, WhenMissing, Always };

// The paper's user scale s of the UV pass's texel density (its Figure 3 studies 0.1 to 2): the
// range an object's uv_scale takes.
constexpr double kMinUvScale = 0.01;
constexpr double kMaxUvScale = 100.0;

struct ObjectDescription {
  std::variant<MeshFile, BuiltinObject, GivenObject, RoomObject> source;
  UvPassMode uv_pass = UvPassMode::Never;
  double uv_scale = 1.0;  // the UV pass's texel_density_scale, when it runs
  glm::dmat4 object_to_world{1.0};
  // Scene materials by name: `material` for every part, or `part_materials` by part name. Parts
  // not covered keep the object's own materials (glTF slots, built-in materials).
  std::optional<std::string> material;
  std::map<std::string, std::string> part_materials;
  // Cycles' Shading > Shadow Terminator > Geometry Offset of the object (Blender's default 0.1).
  float shadow_terminator_geometry_offset = 0.1f;
  // Around the subject rather than the subject: left out of the bounds and the centroid that the
  // paper's rig and a grid camera are placed by (BuiltScene::bounds), so a floor under an object
  // does not move its lamps or its cameras.
  bool surroundings = false;
  Origin origin;
};

// The paper's light rig around the minimal enclosing sphere of all objects.
struct LightRigDescription {
  std::optional<double> target_illuminance_lux;
};
using LightsDescription = std::variant<std::vector<Lamp>, LightRigDescription>;

// World > Environment Texture: an equirectangular image file times a strength, turned about Z
// (matrender/background.h).
struct EnvironmentDescription {
  std::string path;                       // resolved against the scene file's folder
  std::optional<ColorSpace> color_space;  // none: Blender's default for the file (texture.h)
  double strength = 1.0;
  double rotation_z = 0.0;  // radians
  Origin origin;
};
// World > Sky Texture (Nishita) on the Background's Color (matrender/sky.h); sky.strength is the
// Background's Strength.
struct SkyDescription {
  NishitaSky sky;
  Origin origin;
};
// A uniform radiance, an environment map or a sky.
using BackgroundDescription = std::variant<glm::vec3, EnvironmentDescription, SkyDescription>;

struct LookAtPlacement {
  glm::dvec3 position{0.0};
  glm::dvec3 target{0.0};
  glm::dvec3 up{0.0, 0.0, 1.0};
};
struct GridPlacement {
  matgeom::CameraGridSpec spec;
  bool center_on_centroid = true;  // spec.center becomes the surface centroid of all objects
  int i = 0;
  int j = 0;
};
struct MatrixPlacement {
  glm::dmat4 camera_to_world{1.0};
};

using CameraPlacement = std::variant<LookAtPlacement, GridPlacement, MatrixPlacement>;

struct CameraDescription {
  CameraPlacement placement;
  double vertical_fov = Camera{}.vertical_fov;
  int width = Camera{}.width;
  int height = Camera{}.height;
};

struct SceneDescription {
  CameraDescription camera;
  LightsDescription lights = LightRigDescription{};
  BackgroundDescription background = glm::vec3(0.0f);
  std::map<std::string, MaterialDescription> materials;
  std::vector<ObjectDescription> objects;
  // Samples, seed, bounces and background transparency; threads, AOVs, progress and
  // cancellation belong to the run, not the scene, and are set by the app.
  RenderSettings settings;
  double exposure_stops = 0.0;
};

}  // namespace matrender
