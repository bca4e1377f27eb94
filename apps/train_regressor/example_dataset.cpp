#include "example_dataset.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "matgeom/bounding_sphere.h"
#include "matgeom/builtin_objects.h"
#include "matgeom/camera_grid.h"
#include "matgeom/material_classes.h"
#include "matrender/asset.h"
#include "matrender/camera.h"
#include "matrender/image_io.h"
#include "matrender/paper_setup.h"
#include "matrender/render.h"

namespace train_regressor {
namespace {

// One material of a variant: a constant Principled material of one of the repository's classes.
struct ExampleMaterial {
  const char* name;
  matgeom::MaterialClass family;
  std::array<float, 3> base_color;  // linear
  float roughness, metallic;
};

constexpr std::array<ExampleMaterial, 4> kMaterials = {{
    {"wood_1", matgeom::MaterialClass::Wood, {0.30f, 0.14f, 0.05f}, 0.60f, 0.0f},
    {"metal_1", matgeom::MaterialClass::Metal, {0.80f, 0.80f, 0.82f}, 0.25f, 1.0f},
    {"plastic_1", matgeom::MaterialClass::Plastic, {0.60f, 0.05f, 0.04f}, 0.35f, 0.0f},
    {"fabric_1", matgeom::MaterialClass::Fabric, {0.10f, 0.25f, 0.55f}, 0.90f, 0.0f},
}};
constexpr std::array<const char*, 2> kObjects = {"vase", "chair"};

std::string three_digits(int n) { return fmt::format("{:03d}", n); }

void render_variant(const matgeom::ObjectAsset& asset, const ExampleMaterial& m, const std::filesystem::path& folder,
                    const ExampleDatasetSize& size, uint32_t seed) {
  matrender::Scene scene;
  matrender::Material material;
  material.name = m.name;
  material.label_id = matgeom::label_id(m.family);
  material.set(matrender::MaterialParameter::BaseColor, glm::vec3(m.base_color[0], m.base_color[1], m.base_color[2]));
  material.set(matrender::MaterialParameter::Roughness, m.roughness);
  material.set(matrender::MaterialParameter::Metallic, m.metallic);
  const uint32_t id = scene.add_material(material);
  // Every part in the variant's material, whatever the object's own materials.
  const size_t parts = std::max<size_t>({asset.mesh.part_count(), asset.materials.size(), 1});
  matrender::add_asset(scene, asset, std::vector<std::optional<uint32_t>>(parts, id));
  const matgeom::Sphere bounds = matgeom::minimal_enclosing_sphere(asset.mesh.positions);
  matrender::add_rig(scene, matrender::paper_rig(bounds));

  // Cameras on a ring 30 degrees above the horizon, far enough for the sphere to fill 90 % of
  // the view.
  const double fov = 0.691111;
  matgeom::CameraGridSpec grid;
  grid.center = bounds.center;
  grid.radius = bounds.radius / std::sin(0.5 * fov) / 0.9;
  grid.phi_min = grid.phi_max = 1.0471975511965976;  // 60 degrees from the zenith
  grid.n_phi = 1;
  grid.theta_min = -3.141592653589793;
  grid.theta_max = 3.141592653589793;
  grid.n_theta = size.views;
  matrender::RenderSettings settings;
  settings.samples_per_pixel = size.samples;
  settings.transparent_background = true;
  using P = matrender::MaterialParameter;
  settings.aovs = matrender::parameter_aov(P::BaseColor) | matrender::parameter_aov(P::Roughness) |
                  matrender::parameter_aov(P::Metallic) | matrender::AovLabel |
                  matrender::AovNormalWorld | matrender::AovAlpha;
  for (int view = 0; view < size.views; ++view) {
    const matrender::Camera camera = matrender::grid_view(grid, 0, view, size.resolution, size.resolution, fov);
    settings.seed = seed + static_cast<uint32_t>(view);
    matrender::FrameBuffers frame;
    matrender::render(scene, camera, settings, frame);
    const std::string stem = three_digits(view) + ".png";
    const int w = frame.width, h = frame.height;
    const size_t pixels = static_cast<size_t>(w) * static_cast<size_t>(h);
    std::filesystem::create_directories(folder / "images");
    std::filesystem::create_directories(folder / "albedo");
    std::filesystem::create_directories(folder / "ORM");
    std::filesystem::create_directories(folder / "label");
    std::filesystem::create_directories(folder / "normal_obj");
    matgeom::write_display_png((folder / "images" / stem).string(), w, h, frame.color.data(), frame.alpha.data());
    // The albedo display-encoded as the repository stores it, covered pixels only.
    std::vector<float> albedo(pixels * 3);
    for (size_t p = 0; p < pixels; ++p)
      for (int c = 0; c < 3; ++c) albedo[p * 3 + static_cast<size_t>(c)] = frame.parameter(P::BaseColor)[p * 3 + static_cast<size_t>(c)] * frame.alpha[p];
    matgeom::write_display_png((folder / "albedo" / stem).string(), w, h, albedo.data(), frame.alpha.data());
    // ORM: R ambient occlusion (1: none is modelled), G roughness, B metallic; normal_obj:
    // 0.5 n + 0.5 of the world-space shading normal. Alpha is 1 where covered, unlike the
    // repository's coverage, so readers that un-premultiply do not inflate edge values (its W6).
    std::vector<float> orm(pixels * 4, 0.0f), normal(pixels * 4, 0.0f);
    for (size_t p = 0; p < pixels; ++p) {
      if (frame.alpha[p] <= 0.0f) continue;
      orm[p * 4 + 0] = 1.0f;
      orm[p * 4 + 1] = frame.parameter(P::Roughness)[p];
      orm[p * 4 + 2] = frame.parameter(P::Metallic)[p];
      for (int c = 0; c < 3; ++c) normal[p * 4 + static_cast<size_t>(c)] = 0.5f * frame.normal_world[p * 3 + static_cast<size_t>(c)] + 0.5f;
      orm[p * 4 + 3] = normal[p * 4 + 3] = 1.0f;
    }
    matgeom::write_data_png((folder / "ORM" / stem).string(), w, h, 4, orm.data(), 255.0, 0.0, false);
    matgeom::write_data_png((folder / "normal_obj" / stem).string(), w, h, 4, normal.data(), 255.0, 0.0, false);
    std::vector<float> label(pixels);
    for (size_t p = 0; p < pixels; ++p) label[p] = static_cast<float>(frame.label[p]);
    matgeom::write_data_png((folder / "label" / stem).string(), w, h, 1, label.data(), 1.0, 0.0, false);
  }
}

}  // namespace

int render_example_dataset(const std::filesystem::path& root, const ExampleDatasetSize& size,
                           const std::function<void(int, int)>& progress) {
  const int total = static_cast<int>(kObjects.size() * kMaterials.size()) * size.views;
  // The marker's first line names the layout; an older one (before normal_obj) is rendered again.
  const std::string version = "matpredict example dataset 2";
  const std::filesystem::path complete = root / "COMPLETE";
  std::string marker;
  std::getline(std::ifstream(complete), marker);
  if (marker == version) return total;
  int done = 0;
  for (size_t o = 0; o < kObjects.size(); ++o) {
    const matgeom::ObjectAsset asset = matgeom::make_builtin_object(kObjects[o]);
    for (size_t v = 0; v < kMaterials.size(); ++v) {
      render_variant(asset, kMaterials[v], root / kObjects[o] / ("var" + three_digits(static_cast<int>(v))), size,
                     static_cast<uint32_t>(100 * o + 10 * v));
      done += size.views;
      if (progress) progress(done, total);
    }
  }
  std::ofstream(complete) << version << "\nrendered by train_regressor: " << kObjects.size() << " objects x " << kMaterials.size()
                          << " materials x " << size.views << " views\n";
  return total;
}

}  // namespace train_regressor
