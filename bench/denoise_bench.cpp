// Prints the denoiser's figures: on built-in objects in library materials under the paper's rig,
// the image's RMSE against a converged reference (percent of the object's mean) at several
// sample counts, raw and denoised, with the time each took (render, then the filter), in one run.
#include <cmath>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include "image_error.h"
#include "matrender/paper_setup.h"
#include "matrender/render.h"
#include "matrender/scene_builder.h"

namespace {

struct Case {
  std::string object, material;
};

matrender::BuiltScene object_in_material(const Case& c, int material_resolution) {
  matrender::SceneDescription scene;
  matrender::MaterialDescription material;
  material.library = matrender::LibraryMaterialRequest{matgeom::parse_library_material(c.material), material_resolution, {}};
  scene.materials.emplace("material", material);
  matrender::ObjectDescription object;
  object.source = matrender::BuiltinObject{c.object, 0};
  object.material = "material";
  scene.objects.push_back(object);
  scene.lights = matrender::LightRigDescription{matrender::kPaperTargetIlluminanceLux};
  scene.camera.placement = matrender::MatrixPlacement{};
  return matrender::build_scene(scene);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"denoise_bench: the denoiser's error against a converged reference, raw beside denoised"};
  int resolution = 192, reference_spp = 2048, threads = 2;
  std::vector<int> spps{4, 16, 64, 128};
  std::vector<std::string> cases{"vase:wood:1", "chair:fabric:1", "vase:metal:1"};
  app.add_option("--resolution", resolution, "image side in pixels")->capture_default_str();
  app.add_option("--reference-spp", reference_spp, "samples per pixel of the reference")->capture_default_str();
  app.add_option("--spp", spps, "sample counts compared")->capture_default_str();
  app.add_option("--cases", cases, "OBJECT:MATERIAL (a library spec)")->capture_default_str();
  app.add_option("--threads", threads, "render threads")->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  fmt::print("## Denoising: RMSE against a {} spp reference, % of the object's mean, {}x{}, {} threads\n\n",
             reference_spp, resolution, resolution, threads);
  fmt::print("| object | material | spp | raw RMSE | raw s | denoised RMSE | denoised s |\n|---|---|---:|---:|---:|---:|---:|\n");
  for (const std::string& spec : cases) {
    const size_t colon = spec.find(':');
    const Case c{spec.substr(0, colon), spec.substr(colon + 1)};
    matrender::BuiltScene built = object_in_material(c, 512);
    matgeom::CameraGridSpec grid;
    grid.center = built.bounds.center;
    const double fov = 0.6911;
    grid.radius = built.bounds.radius / std::sin(0.5 * fov) / 0.9;
    grid.n_phi = grid.n_theta = 2;
    const matrender::Camera camera = matrender::grid_view(grid, 1, 1, resolution, resolution, fov);
    matrender::RenderSettings settings;
    settings.threads = threads;
    settings.transparent_background = true;
    settings.aovs = matrender::AovAlpha;
    settings.samples_per_pixel = reference_spp;
    settings.seed = 1000;
    matrender::FrameBuffers reference;
    matrender::render(built.scene, camera, settings, reference);
    const double brightness = bench::mean(reference.color) / std::max(bench::mean(reference.alpha), 1e-9);
    for (const int spp : spps) {
      settings.samples_per_pixel = spp;
      settings.seed = 1;
      std::string row = fmt::format("| {} | {} | {} ", c.object, c.material, spp);
      for (const bool denoised : {false, true}) {
        settings.denoise = denoised;
        matrender::FrameBuffers frame;
        const matrender::RenderStats stats = matrender::render(built.scene, camera, settings, frame);
        row += fmt::format("| {:.2f} % | {:.3f} ", 100.0 * bench::rmse(frame.color, reference.color) / brightness, stats.seconds);
      }
      fmt::print("{}|\n", row);
    }
  }
  return 0;
}
