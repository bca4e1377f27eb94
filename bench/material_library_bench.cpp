// What the procedural material library costs: the time to generate each style's maps at 1k, 2k
// and 4k texels a side, and the time to render the vase in it (the paper's rig, grid cell
// (5, 16), equal spp) against the vase in a plain untextured diffuse material, both measured in
// this run. Timings, not tests: run it on a quiet machine.
#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "matbase/threads.h"
#include "matgeom/bounding_sphere.h"
#include "matgeom/builtin/builtin_objects.h"
#include "matgeom/camera_grid.h"
#include "matgeom/uv/uv_scale.h"
#include "matmaterial/library/material_library.h"
#include "matrender/asset.h"
#include "matrender/paper_setup.h"
#include "matrender/render.h"

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// The least render time of `repeats` renders of the vase dressed in `material`.
double render_seconds(const matgeom::ObjectAsset& vase, int size, int spp, int repeats, int threads) {
  matrender::Scene scene;
  matrender::add_asset(scene, vase);
  matrender::add_rig(scene, matrender::paper_rig(vase.mesh));
  const matgeom::Sphere sphere = matgeom::minimal_enclosing_sphere(vase.mesh.positions);
  matgeom::CameraGridSpec spec;
  spec.center = sphere.center;
  spec.radius = 1.05 * sphere.radius / std::sin(0.5 * 0.69);
  const matrender::Camera camera =
      matrender::grid_view(spec, matrender::kPaperViewRow, matrender::kPaperViewColumn, size, size, 0.69);
  matrender::RenderSettings settings;
  settings.samples_per_pixel = spp;
  settings.threads = threads;
  settings.aovs = 0;
  double best = 1e30;
  for (int r = 0; r < repeats; ++r) {
    matrender::FrameBuffers frame;
    best = std::min(best, matrender::render(scene, camera, settings, frame).seconds);
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"material_library_bench: generation time per style at 1k, 2k, 4k and render cost against plain diffuse"};
  std::vector<int> resolutions = {1024, 2048, 4096};
  int size = 128, spp = 64, repeats = 3, threads = 0, render_resolution = 1024;
  app.add_option("--resolutions", resolutions, "map sizes to time generation at")->capture_default_str();
  app.add_option("--size", size, "render width and height")->capture_default_str()->check(CLI::Range(8, 2048));
  app.add_option("--spp", spp, "samples per pixel")->capture_default_str()->check(CLI::Range(1, 65536));
  app.add_option("--repeats", repeats, "renders per material, the fastest kept")
      ->capture_default_str()
      ->check(CLI::Range(1, 100));
  app.add_option("--threads", threads, "worker threads, 0 every hardware thread")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  app.add_option("--render-resolution", render_resolution, "map size of the rendered materials")
      ->capture_default_str()
      ->check(CLI::Range(matmaterial::kMinLibraryResolution, matmaterial::kMaxLibraryResolution));
  CLI11_PARSE(app, argc, argv);
  for (const int r : resolutions)
    if (r < matmaterial::kMinLibraryResolution || r > matmaterial::kMaxLibraryResolution) {
      fmt::print(stderr, "material_library_bench: --resolutions: {} is outside [{}, {}]\n", r,
                 matmaterial::kMinLibraryResolution, matmaterial::kMaxLibraryResolution);
      return 2;
    }
  try {
    const int workers = matbase::worker_threads(threads);
    fmt::print("{} threads; render: vase {}x{} at {} spp, fastest of {}, maps at {}\n\n", workers, size, size, spp,
               repeats, render_resolution);

    matgeom::ObjectAsset plain = matgeom::make_builtin_object("vase", 0);
    plain.images.clear();
    for (matmaterial::MaterialInputs& slot : plain.materials) slot = matmaterial::MaterialInputs(slot.name);  // Blender's default
    const double plain_seconds = render_seconds(plain, size, spp, repeats, threads);

    std::string header = fmt::format("{:<22}", "style");
    for (const int r : resolutions) header += fmt::format(" | {:>6} s", r);
    fmt::print("{} | render s | vs plain\n", header);
    fmt::print("{:<22} {} | {:8.3f} | {:8.2f}\n", "plain diffuse", std::string(resolutions.size() * 11, ' '),
               plain_seconds, 1.0);
    for (const matmaterial::LibraryStyleInfo& style : matmaterial::library_styles()) {
      const matmaterial::LibraryMaterialSpec spec{style.material_class, style.name, 0};
      std::string row =
          fmt::format("{:<22}", std::string(matmaterial::material_class(style.material_class).name) + "/" + style.name);
      for (const int r : resolutions) {
        const Clock::time_point start = Clock::now();
        const matmaterial::FolderMaterial generated = matmaterial::generate_library_material(spec, {r, threads});
        row += fmt::format(" | {:8.3f}", seconds_since(start));
      }
      matgeom::ObjectAsset vase = matgeom::make_builtin_object("vase", 0);
      matgeom::assign_material_to_all_parts(vase,
                                            matmaterial::generate_library_material(spec, {render_resolution, threads}));
      const double seconds = render_seconds(vase, size, spp, repeats, threads);
      fmt::print("{} | {:8.3f} | {:8.2f}\n", row, seconds, seconds / plain_seconds);
    }
  } catch (const std::exception& e) {
    fmt::print(stderr, "material_library_bench: {}\n", e.what());
    return 1;
  }
  return 0;
}
