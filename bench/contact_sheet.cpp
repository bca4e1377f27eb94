// Renders built-in objects under the paper's light rig (normalised to 1 klx) from grid cell
// (5, 16), each framed to fit its bounding sphere, and writes them side by side into one display
// PNG, row by row: the contact sheets in the README. By default every built-in object in its own
// materials; --library OBJECT renders one object in every style of the procedural material
// library, --class CLASS every object in that class's library materials.
#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "bench_scenes.h"
#include "matbase/image/image_writing.h"
#include "matgeom/bounding_sphere.h"
#include "matgeom/builtin/builtin_objects.h"
#include "matgeom/camera_grid.h"
#include "matgeom/uv/uv_scale.h"
#include "matmaterial/library/material_library.h"
#include "matrender/asset.h"
#include "matrender/paper_setup.h"
#include "matrender/render.h"

namespace {

// The paper's grid cell (5, 16) at the distance where the bounding sphere fills the view.
matrender::Camera framed_camera(const matgeom::TriangleMesh& mesh, int size, double vertical_fov) {
  const matgeom::Sphere sphere = matgeom::minimal_enclosing_sphere(mesh.positions);
  matgeom::CameraGridSpec spec;
  spec.center = sphere.center;
  spec.radius = 1.05 * sphere.radius / std::sin(0.5 * vertical_fov);
  return matrender::grid_view(spec, matrender::kPaperViewRow, matrender::kPaperViewColumn, size, size, vertical_fov);
}

struct Cell {
  std::string object;
  std::optional<matmaterial::LibraryMaterialSpec> material;
  std::string caption;
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"contact_sheet: every built-in object rendered side by side into one PNG"};
  std::string output = "docs/images/builtin_objects.png";
  int size = 160, spp = 64, columns = 6;
  uint32_t seed = 0;
  double exposure = 1.5;  // 1 klx indoor light reads dark at exposure 0
  app.add_option("--output", output, "PNG to write")->capture_default_str();
  app.add_option("--size", size, "pixels per object")->capture_default_str()->check(CLI::Range(16, 2048));
  app.add_option("--spp", spp, "samples per pixel")->capture_default_str()->check(CLI::Range(1, 65536));
  app.add_option("--columns", columns, "objects per row")->capture_default_str()->check(CLI::Range(1, 64));
  app.add_option("--seed", seed, "object seed")->capture_default_str();
  app.add_option("--exposure", exposure, "display exposure in stops")->capture_default_str();
  std::optional<std::string> library_object, library_class;
  int material_resolution = 512;
  app.add_option("--library", library_object, "render this built-in object in every style of the material library")
      ->type_name("OBJECT");
  app.add_option("--class", library_class,
                 "render every built-in object in this class's library materials (the seed picks each style)")
      ->type_name("CLASS")
      ->excludes("--library");
  app.add_option("--material-resolution", material_resolution, "texels along each side of a library material's maps")
      ->capture_default_str()
      ->check(CLI::Range(matmaterial::kMinLibraryResolution, matmaterial::kMaxLibraryResolution));
  CLI11_PARSE(app, argc, argv);

  std::vector<Cell> cells;
  const std::vector<std::string> objects = matgeom::builtin_object_names();
  if (library_object) {
    if (std::find(objects.begin(), objects.end(), *library_object) == objects.end()) {
      fmt::print(stderr, "contact_sheet: --library: no built-in object \"{}\"\n", *library_object);
      return 2;
    }
    for (const matmaterial::LibraryStyleInfo& style : matmaterial::library_styles()) {
      const matmaterial::LibraryMaterialSpec spec{style.material_class, style.name,
                                              seed + static_cast<uint32_t>(cells.size())};
      cells.push_back({*library_object, spec, matmaterial::library_material_name(spec)});
    }
  } else if (library_class) {
    matmaterial::LibraryMaterialSpec spec;
    try {
      spec = matmaterial::parse_library_material(*library_class);
    } catch (const std::invalid_argument& e) {
      fmt::print(stderr, "contact_sheet: --class: {}\n", e.what());
      return 2;
    }
    for (size_t k = 0; k < objects.size(); ++k) {
      spec.seed = seed + static_cast<uint32_t>(k);
      cells.push_back({objects[k], spec, objects[k] + " in " + matmaterial::library_material_name(spec)});
    }
  } else {
    for (const std::string& object : objects) cells.push_back({object, std::nullopt, object});
  }

  try {
    const int rows = (static_cast<int>(cells.size()) + columns - 1) / columns;
    const int width = columns * size, height = rows * size;
    std::vector<float> sheet(static_cast<size_t>(width) * static_cast<size_t>(height) * 3, 0.0f);
    for (size_t k = 0; k < cells.size(); ++k) {
      matgeom::ObjectAsset asset = matgeom::make_builtin_object(cells[k].object, seed);
      if (cells[k].material)
        matgeom::assign_material_to_all_parts(
            asset, matmaterial::generate_library_material(*cells[k].material, {material_resolution, 0}));
      matrender::Scene scene;
      matrender::add_asset(scene, asset);
      matrender::add_rig(scene, matrender::paper_rig(asset.mesh));
      matrender::RenderSettings settings;
      settings.samples_per_pixel = spp;
      settings.aovs = 0;
      matrender::FrameBuffers frame;
      const matrender::RenderStats stats =
          matrender::render(scene, framed_camera(asset.mesh, size, 0.69), settings, frame);
      fmt::print("{:>28}: {:>6} triangles, {} parts, {:.2f} s\n", cells[k].caption, asset.mesh.triangle_count(),
                 asset.mesh.part_names.size(), stats.seconds);
      const int x0 = static_cast<int>(k) % columns * size, y0 = static_cast<int>(k) / columns * size;
      for (int y = 0; y < size; ++y)
        std::copy_n(&frame.color[3 * static_cast<size_t>(y) * static_cast<size_t>(size)], 3 * size,
                    &sheet[3 * (static_cast<size_t>(y0 + y) * static_cast<size_t>(width) + static_cast<size_t>(x0))]);
    }
    matbase::write_display_png(output, width, height, sheet.data(), nullptr, exposure);
    fmt::print("wrote {} ({} x {})\n", output, width, height);
  } catch (const std::exception& e) {
    fmt::print(stderr, "contact_sheet: {}\n", e.what());
    return 1;
  }
  return 0;
}
