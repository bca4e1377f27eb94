// Prints the UV pass's figures against triangle count: time, memory, charts and tiles, angle
// distortion, area stretch, packing efficiency and achieved against target texel density, for
// bumpy closed spheres (a scanned-looking surface with no sharp edges to cut along) and the
// built-in objects.
#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include "bench_scenes.h"
#include "matgeom/builtin/builtin_objects.h"
#include "matgeom/uv/uv_pass.h"

namespace {

using Clock = std::chrono::steady_clock;

struct Measured {
  matgeom::UvPassResult result;
  double seconds = 0.0;
  double extra_mib = 0.0;  // peak resident memory during the pass above what was resident before
};

Measured measure_uv_pass(const matgeom::TriangleMesh& mesh, const matgeom::UvPassOptions& options) {
  Measured measured;
  const double before = bench::rss_mib();
  bench::reset_peak_rss();
  const auto start = Clock::now();
  measured.result = matgeom::uv_pass(mesh, options);
  measured.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  measured.extra_mib = bench::peak_rss_mib() - before;
  return measured;
}

void print_header() {
  fmt::print("| mesh | triangles | seconds | extra peak MiB | charts | tiles | angle mean / max (rad) | "
             "stretch L2 / Linf | packing | density achieved / target (px/m) |\n");
  fmt::print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
}

// One row per part of the mesh.
void print_rows(const std::string& name, const matgeom::TriangleMesh& mesh, const Measured& measured) {
  for (const matgeom::UvPartReport& part : measured.result.parts) {
    const std::string label = measured.result.parts.size() > 1 ? name + " / " + part.part : name;
    fmt::print("| {} | {} | {:.3f} | {:.0f} | {} | {} | {:.4f} / {:.3f} | {:.3f} / {:.2f} | {:.2f} | {:.1f} / {:.1f} |\n",
               label, mesh.triangle_count(), measured.seconds, measured.extra_mib, part.charts, part.tiles,
               part.distortion.angle_mean, part.distortion.angle_max, part.distortion.stretch_l2,
               part.distortion.stretch_linf, part.packing_efficiency, part.achieved_density, part.target_density);
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"uv_pass_bench: the UV pass's time, memory, distortion and packing against triangle count"};
  std::vector<size_t> sizes = {10'000, 100'000, 1'000'000};
  double scale = 1.0;
  bool objects = true;
  app.add_option("--triangles", sizes, "sizes of the bumpy spheres")->capture_default_str();
  app.add_option("--scale", scale, "the paper's texel density scale s")->capture_default_str();
  app.add_flag("!--no-objects", objects, "skip the table of built-in objects");
  CLI11_PARSE(app, argc, argv);

  matgeom::UvPassOptions options;
  options.texel_density_scale = scale;
  fmt::print("## UV pass on bumpy spheres (radius about 0.3 m, s = {}, {}-pixel tiles, 1 thread)\n\n", scale,
             options.tile_resolution);
  print_header();
  for (const size_t target : sizes) {
    const matgeom::TriangleMesh mesh = bench::displaced_sphere(target);
    print_rows("bumpy sphere", mesh, measure_uv_pass(mesh, options));
  }
  if (objects) {
    fmt::print("\n## UV pass on the built-in objects (seed 0), per part\n\n");
    print_header();
    for (const std::string& name : matgeom::builtin_object_names()) {
      matgeom::TriangleMesh mesh = matgeom::make_builtin_object(name, 0).mesh;
      mesh.uvs.clear();
      mesh.tangents.clear();
      print_rows(name, mesh, measure_uv_pass(mesh, options));
    }
  }
  return 0;
}
