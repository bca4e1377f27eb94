// Material folders rendered: a scene file's {"matsynth": folder} material shades with the folder's
// maps (its AOVs are the maps' values, its label the folder's class), and a DirectX normal map
// tilts the surface the same way as the OpenGL one it is the mirror of.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <optional>
#include <fstream>
#include <string>
#include <vector>

#include "matbase/image/png_encoding.h"
#include "matbase/image/srgb.h"
#include "matgeom/io/mesh_io.h"
#include "matgeom/tangents.h"
#include "matgeom/uv/uv_scale.h"
#include "matmaterial/folder/material_folder.h"
#include "matrender/asset.h"
#include "matrender/material.h"
#include "matrender/scene_builder.h"
#include "matrender/scene_file.h"
#include "test_scenes.h"

using namespace matrender;

namespace {

std::filesystem::path fresh_folder(const std::string& name) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("matpredict_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(path);
  std::filesystem::create_directories(path);
  return path;
}

matbase::ImagePixels uniform_image(int size, uint8_t r, uint8_t g, uint8_t b) {
  matbase::ImagePixels image{"uniform", size, size, 4, std::vector<uint8_t>(static_cast<size_t>(size * size) * 4u)};
  for (size_t k = 0; k < image.data.size(); k += 4) {
    image.data[k] = r;
    image.data[k + 1] = g;
    image.data[k + 2] = b;
    image.data[k + 3] = 255;
  }
  return image;
}

void write_png(const std::filesystem::path& path, const matbase::ImagePixels& image) {
  std::ofstream(path, std::ios::binary) << matbase::encode_png(image, path.string());
}

// Mean colour of a plane lit from +v (light_toward_plus_v) or from -v, its material read from a
// folder holding only a normal map, tilted toward +v in OpenGL's terms.
double lit_mean(const std::filesystem::path& folder, bool light_toward_plus_v) {
  const matmaterial::FolderMaterial read = matmaterial::read_material_folder(folder.string());
  Material material = material_from_desc(read.material, read.images);
  matgeom::TriangleMesh plane = test_scenes::horizontal_square(2.0);
  plane.normals.assign(plane.positions.size(), glm::vec3(0.0f, 0.0f, 1.0f));
  matgeom::compute_tangents(plane);
  Scene scene;
  scene.add_mesh(plane, {scene.add_material(material)});
  // A point lamp low over the plane on the +y (+v) or -y side.
  scene.add_lamp(PointLamp{glm::dvec3(0.0, light_toward_plus_v ? 3.0 : -3.0, 0.8), 200.0, glm::dvec3(1.0)});
  const Camera camera = Camera::look_at({0, 0, 3}, {0, 0, 0}, {0, 1, 0}, 0.5, 16, 16);
  RenderSettings settings;
  settings.samples_per_pixel = 4;
  FrameBuffers frame;
  render(scene, camera, settings, frame);
  return test_scenes::mean_of(frame.color);
}

}  // namespace

TEST_CASE("A scene file's material folder shades with its maps and is labelled with its class", "[render]") {
  const std::filesystem::path root = fresh_folder("folder_scene");
  const std::filesystem::path folder = root / "fabric_test";
  std::filesystem::create_directories(folder);
  write_png(folder / "basecolor.png", uniform_image(8, 128, 64, 200));
  write_png(folder / "roughness.png", uniform_image(4, 64, 64, 64));  // another size: resampled
  std::ofstream(folder / "metadata.json") << R"({"parameters": {"sheen": 0.5}})";
  std::ofstream(root / "scene.json") << R"({
    "camera": { "position": [0.6, -0.6, 0.35], "look_at": [0, 0, 0.15], "width": 32, "height": 32 },
    "lights": [ { "type": "point", "position": [0, -1, 1], "power": 20 } ],
    "materials": { "cloth": { "matsynth": "fabric_test" } },
    "objects": [ { "builtin": "vase", "material": "cloth" } ],
    "render": { "spp": 2 }
  })";
  const SceneDescription description = read_scene_file((root / "scene.json").string());
  BuiltScene built = build_scene(description);
  RenderSettings settings = description.settings;
  settings.aovs = all_aovs();
  FrameBuffers frame;
  render(built.scene, built.camera, settings, frame);
  int hits = 0;
  for (size_t i = 0; i < frame.label.size(); ++i) {
    if (frame.alpha[i] < 1.0f) continue;  // the silhouette blends with the background
    ++hits;
    CHECK(frame.label[i] == matmaterial::label_id(matmaterial::MaterialClass::Fabric));
    const std::vector<float>& base = frame.parameter(MaterialParameter::BaseColor);
    CHECK(base[3 * i] == Approx(matbase::srgb_to_linear(128.0 / 255.0)).epsilon(1e-4));
    CHECK(base[3 * i + 1] == Approx(matbase::srgb_to_linear(64.0 / 255.0)).epsilon(1e-4));
    CHECK(base[3 * i + 2] == Approx(matbase::srgb_to_linear(200.0 / 255.0)).epsilon(1e-4));
    CHECK(frame.parameter(MaterialParameter::Roughness)[i] == Approx(64.0 / 255.0).epsilon(1e-4));
    CHECK(frame.parameter(MaterialParameter::Metallic)[i] == 0.0f);
    CHECK(frame.parameter(MaterialParameter::Sheen)[i] == Approx(0.5f));
  }
  CHECK(hits > 50);

  // The same folder given in place on the object.
  std::ofstream(root / "inline.json") << R"({
    "camera": { "position": [0.6, -0.6, 0.35], "look_at": [0, 0, 0.15], "width": 8, "height": 8 },
    "lights": [ { "type": "point", "position": [0, -1, 1], "power": 20 } ],
    "objects": [ { "builtin": "vase", "material": { "matsynth": "fabric_test" } } ]
  })";
  const SceneDescription inline_description = read_scene_file((root / "inline.json").string());
  REQUIRE(inline_description.objects.size() == 1);
  REQUIRE(inline_description.objects[0].material == std::optional<std::string>("/objects/0/material"));
  const MaterialDescription& inline_material = inline_description.materials.at("/objects/0/material");
  REQUIRE(inline_material.folder);
  CHECK(inline_material.folder->path == (root / "fabric_test").string());
  std::filesystem::remove_all(root);
}

TEST_CASE("A DirectX normal map lights a surface as the OpenGL map it mirrors", "[render]") {
  const std::filesystem::path root = fresh_folder("normal_conventions");
  // Tilted toward +v: OpenGL's green above 128, DirectX's the same amount below.
  std::filesystem::create_directories(root / "gl");
  std::filesystem::create_directories(root / "dx");
  write_png(root / "gl" / "normal_gl.png", uniform_image(4, 128, 200, 200));
  write_png(root / "dx" / "normal_dx.png", uniform_image(4, 128, 255 - 200, 200));
  const double gl_plus = lit_mean(root / "gl", true), gl_minus = lit_mean(root / "gl", false);
  const double dx_plus = lit_mean(root / "dx", true), dx_minus = lit_mean(root / "dx", false);
  INFO("OpenGL map: lit from +v " << gl_plus << ", from -v " << gl_minus << "; DirectX map: " << dx_plus << ", "
                                  << dx_minus);
  // Facing +v, the surface is brighter under the lamp on that side, by far more than noise.
  CHECK(gl_plus > 1.5 * gl_minus);
  CHECK(dx_plus == Approx(gl_plus).epsilon(0.02));
  CHECK(dx_minus == Approx(gl_minus).epsilon(0.02));
  std::filesystem::remove_all(root);
}

TEST_CASE("A folder's physical size sets how often its maps repeat on a part", "[render]") {
  // A 2 m plane mapped once onto the UV square, in a folder whose maps are 0.5 m long: a base
  // colour dark on its left half and light on its right repeats four times across the plane.
  const std::filesystem::path root = fresh_folder("folder_tiles");
  const std::filesystem::path folder = root / "stripes";
  std::filesystem::create_directories(folder);
  matbase::ImagePixels halves = uniform_image(8, 20, 20, 20);
  for (int y = 0; y < 8; ++y)
    for (int x = 4; x < 8; ++x)
      for (int c = 0; c < 3; ++c) halves.data[static_cast<size_t>(y * 8 + x) * 4u + static_cast<size_t>(c)] = 230;
  write_png(folder / "basecolor.png", halves);
  std::ofstream(folder / "metadata.json") << R"({"physical_size": 50})";
  matgeom::TriangleMesh plane = test_scenes::horizontal_square(2.0);
  plane.normals.assign(plane.positions.size(), glm::vec3(0.0f, 0.0f, 1.0f));
  plane.part_names = {"plane"};
  const std::filesystem::path mesh_file = root / "plane.ply";
  matgeom::ObjectAsset asset;
  asset.mesh = plane;
  asset.materials = {matmaterial::MaterialInputs("plane")};
  matgeom::write_object(asset, mesh_file.string());
  std::ofstream(root / "scene.json") << R"({
    "camera": { "position": [0, 0, 3], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov_deg": 4.65, "width": 64, "height": 8 },
    "lights": [ { "type": "point", "position": [0, 0, 2], "power": 20 } ],
    "objects": [ { "mesh": "plane.ply", "material": { "matsynth": "stripes" } } ],
    "render": { "spp": 4 }
  })";
  const SceneDescription description = read_scene_file((root / "scene.json").string());
  BuiltScene built = build_scene(description);
  RenderSettings settings = description.settings;
  settings.aovs = parameter_aov(MaterialParameter::BaseColor);
  FrameBuffers frame;
  render(built.scene, built.camera, settings, frame);
  // Along the middle row, count the steps between dark and light.
  const std::vector<float>& base = frame.parameter(MaterialParameter::BaseColor);
  int steps = 0;
  bool light = base[3 * (4 * 64)] > 0.3f;
  for (int x = 1; x < 64; ++x) {
    const bool now = base[3 * static_cast<size_t>(4 * 64 + x)] > 0.3f;
    steps += now != light;
    light = now;
  }
  // 4.65 degrees high and 8 times as wide from 3 m, the camera sees 1.95 m of the 2 m plane: 3.9 repeats, 7 or 8 steps (2 without
  // the physical size).
  CHECK(steps >= 7);
  CHECK(steps <= 8);
  std::filesystem::remove_all(root);
}

TEST_CASE("A material repeated for export reads its maps where the renderer's repeated material does", "[render]") {
  // make_dataset renders a library material repeated by matrender::with_texture_repeats and
  // exports the same variant (glTF, for Blender) repeated by matgeom::with_texture_repeats: both
  // must put each map at the same place, or the exported object shows its pattern shifted (by
  // k - 1 tiles in v, as the hammered metal's dents were). Non-integer repeats, so that a shift
  // cannot hide as whole tiles.
  const std::vector<matbase::ImagePixels> images = {uniform_image(2, 128, 128, 255), uniform_image(2, 200, 100, 50)};
  for (const matmaterial::TextureTransform& placement :
       {matmaterial::TextureTransform{}, matmaterial::TextureTransform{{0.25, -0.5}, 0.75, {2.0, 3.0}}}) {
    for (const double k : {1.46093, 4.0, 0.3}) {
      matmaterial::MaterialInputs desc("tiled");
      desc.normal_image = 0;
      desc.normal_transform = placement;
      desc.set_image(MaterialParameter::BaseColor, 1);
      desc[MaterialParameter::BaseColor].transform = placement;
      const Material rendered = with_texture_repeats(material_from_desc(desc, images), static_cast<float>(k));
      const Material exported = material_from_desc(matgeom::with_texture_repeats(desc, k), images);
      for (const glm::vec2 uv : {glm::vec2(0.0f), glm::vec2(1.0f, 0.0f), glm::vec2(0.3f, 0.8f), glm::vec2(-1.5f, 2.25f)}) {
        const glm::vec2 a = rendered.normal_map_uv_transform.apply(uv);
        const glm::vec2 b = exported.normal_map_uv_transform.apply(uv);
        CHECK(glm::length(a - b) < 1e-4f);
        const glm::vec2 c = rendered[MaterialParameter::BaseColor].uv_transform.apply(uv);
        const glm::vec2 d = exported[MaterialParameter::BaseColor].uv_transform.apply(uv);
        CHECK(glm::length(c - d) < 1e-4f);
      }
    }
  }
}
