// Blender 3.4 Cycles beside libmatrender on the same scene, in one run: the bumpy sphere of
// render_bench in the bench material under the paper's rig, rendered by both at the same
// sample counts and threads. Prints each renderer's time and error against its own converged
// reference, the time each needs to reach the same error (and their ratio), and how far the two
// converged images are apart (accuracy). Needs Debian's `blender` (3.4) on PATH or --blender;
// Blender is a reference here, never a dependency of the product.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <OpenImageIO/imageio.h>
#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "bench_scenes.h"
#include "matrender/render.h"

#ifndef MATPREDICT_BENCH_SOURCE_DIR
#error "MATPREDICT_BENCH_SOURCE_DIR must name bench/ (for cycles_render.py)"
#endif

namespace {

using nlohmann::json;

json column_major(const glm::dmat4& m) {
  json values = json::array();
  for (int column = 0; column < 4; ++column)
    for (int row = 0; row < 4; ++row) values.push_back(m[column][row]);
  return values;
}

// What cycles_render.py rebuilds in Blender.
json describe_scene(const matgeom::TriangleMesh& mesh, const matrender::Material& material,
                    const std::vector<matrender::Light>& lights, const matrender::Camera& camera) {
  json scene;
  json positions = json::array(), normals = json::array(), triangles = json::array();
  for (const glm::vec3& p : mesh.positions) positions.push_back({p.x, p.y, p.z});
  for (const glm::vec3& n : mesh.normals) normals.push_back({n.x, n.y, n.z});
  for (const glm::uvec3& t : mesh.triangles) triangles.push_back({t.x, t.y, t.z});
  scene["mesh"] = {{"positions", positions}, {"normals", normals}, {"triangles", triangles}};
  const glm::vec3 base = material.base_color.value;
  scene["material"] = {{"base_color", {base.r, base.g, base.b}},
                       {"metallic", material.metallic.value},
                       {"roughness", material.roughness.value},
                       {"specular", material.specular},
                       {"specular_tint", material.specular_tint}};
  json lamps = json::array();
  for (const matrender::Light& light : lights) {
    const auto* rect = std::get_if<matrender::RectLight>(&light);
    if (!rect) throw std::runtime_error("cycles_side_by_side: only rectangle lamps are exported to Blender");
    lamps.push_back({{"light_to_world", column_major(rect->light_to_world)},
                     {"size_x", rect->size_x},
                     {"size_y", rect->size_y},
                     {"power", rect->power},
                     {"color", {rect->color.r, rect->color.g, rect->color.b}}});
  }
  scene["lamps"] = lamps;
  scene["camera"] = {{"camera_to_world", column_major(camera.camera_to_world)},
                     {"vertical_fov", camera.vertical_fov},
                     {"width", camera.width},
                     {"height", camera.height}};
  scene["background"] = {0.0, 0.0, 0.0};
  return scene;
}

std::vector<float> read_rgb_exr(const std::string& path, int width, int height) {
  auto input = OIIO::ImageInput::open(path);
  if (!input) throw std::runtime_error(path + ": cannot open: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = input->spec();
  if (spec.width != width || spec.height != height || spec.nchannels < 3)
    throw std::runtime_error(path + ": expected " + std::to_string(width) + "x" + std::to_string(height) + " RGB");
  std::vector<float> rgb(static_cast<size_t>(width) * height * 3);
  if (!input->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, rgb.data()))
    throw std::runtime_error(path + ": " + input->geterror());
  return rgb;
}

double rmse(const std::vector<float>& a, const std::vector<float>& b) {
  double sum = 0.0;
  for (size_t i = 0; i < a.size(); ++i) sum += (double(a[i]) - b[i]) * (double(a[i]) - b[i]);
  return std::sqrt(sum / a.size());
}

double mean(const std::vector<float>& a) {
  double sum = 0.0;
  for (const float v : a) sum += v;
  return sum / a.size();
}

struct Curve {
  std::vector<double> seconds, error;  // by increasing sample count
};

// Seconds to reach `target` error, interpolated log-log between the measured points; NaN when
// the curve never gets there.
double seconds_to_reach(const Curve& curve, double target) {
  for (size_t k = 0; k < curve.error.size(); ++k) {
    if (curve.error[k] > target) continue;
    if (k == 0) return curve.seconds[0];
    const double t = (std::log(curve.error[k - 1]) - std::log(target)) /
                     (std::log(curve.error[k - 1]) - std::log(curve.error[k]));
    return std::exp(std::log(curve.seconds[k - 1]) + t * (std::log(curve.seconds[k]) - std::log(curve.seconds[k - 1])));
  }
  return std::nan("");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"cycles_side_by_side: libmatrender beside Blender 3.4 Cycles, time to the same error"};
  size_t triangles = 10'000;
  int resolution = 256, threads = 2, reference_spp = 1024;
  std::vector<int> spp_list = {1, 4, 16, 64, 256};
  std::string blender = "blender", work = "cycles_side_by_side_out";
  app.add_option("--triangles", triangles, "triangles of the bumpy sphere")->capture_default_str();
  app.add_option("--resolution", resolution, "image side in pixels")->capture_default_str();
  app.add_option("--threads", threads, "threads for both renderers")->capture_default_str();
  app.add_option("--spp", spp_list, "sample counts to time")->capture_default_str();
  app.add_option("--reference-spp", reference_spp, "samples of each renderer's converged reference")
      ->capture_default_str();
  app.add_option("--blender", blender, "Blender 3.4 executable")->capture_default_str();
  app.add_option("--work", work, "folder for the scene description and Cycles' EXRs")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  std::sort(spp_list.begin(), spp_list.end());

  const matgeom::TriangleMesh mesh = bench::displaced_sphere(triangles);
  const matrender::Material material = bench::bench_material();
  const std::vector<matrender::Light> lights = bench::paper_rig_lights(mesh);
  const matrender::Camera camera = bench::paper_camera(mesh, resolution, resolution);

  std::filesystem::create_directories(work);
  const std::string description_path = work + "/scene.json";
  std::ofstream(description_path) << describe_scene(mesh, material, lights, camera).dump();

  // Cycles first, alone on the machine; its references are rendered last.
  std::string spp_argument;
  for (const int spp : spp_list) spp_argument += std::to_string(spp) + ",";
  spp_argument += std::to_string(reference_spp);
  const std::string command = fmt::format("'{}' -b --factory-startup -noaudio --python-exit-code 1 -P '{}/cycles_render.py' -- '{}' '{}' {} {} > '{}/blender.log' 2>&1",
                                          blender, MATPREDICT_BENCH_SOURCE_DIR, description_path, work, spp_argument,
                                          threads, work);
  fmt::print(stderr, "running Blender: {}\n", command);
  if (std::system(command.c_str()) != 0) {
    fmt::print(stderr, "cycles_side_by_side: Blender failed; see {}/blender.log\n", work);
    return 1;
  }
  json cycles_seconds;
  std::ifstream(work + "/cycles_timings.json") >> cycles_seconds;

  matrender::Scene scene;
  scene.add_mesh(mesh, {scene.add_material(material)});
  for (const matrender::Light& light : lights) scene.add_light(light);
  scene.commit();
  const auto render_ours = [&](int spp, double* seconds) {
    matrender::RenderSettings settings;
    settings.samples_per_pixel = spp;
    settings.threads = threads;
    settings.aovs = 0;
    matrender::FrameBuffers frame;
    *seconds = matrender::render(scene, camera, settings, frame).seconds;
    return frame.color;
  };
  double ours_reference_seconds;
  const std::vector<float> ours_reference = render_ours(reference_spp, &ours_reference_seconds);
  const std::vector<float> cycles_reference =
      read_rgb_exr(work + "/cycles_" + std::to_string(reference_spp) + ".exr", resolution, resolution);

  Curve ours, cycles;
  fmt::print("## libmatrender beside Blender 3.4 Cycles: bumpy sphere, {} triangles, paper rig, {}x{}, {} threads\n\n",
             mesh.triangle_count(), resolution, resolution, threads);
  fmt::print("BVH build (ours): {:.1f} ms. Cycles' times are whole render calls (scene sync, BVH, sampling, EXR).\n\n",
             1e3 * scene.bvh_build_seconds());
  fmt::print("| spp | ours s | ours RMSE | Cycles s | Cycles RMSE |\n|---:|---:|---:|---:|---:|\n");
  for (const int spp : spp_list) {
    double seconds;
    const std::vector<float> image = render_ours(spp, &seconds);
    ours.seconds.push_back(seconds + scene.bvh_build_seconds());
    ours.error.push_back(rmse(image, ours_reference));
    cycles.seconds.push_back(cycles_seconds[std::to_string(spp)].get<double>());
    cycles.error.push_back(rmse(read_rgb_exr(work + "/cycles_" + std::to_string(spp) + ".exr", resolution, resolution),
                                cycles_reference));
    fmt::print("| {} | {:.3f} | {:.5f} | {:.3f} | {:.5f} |\n", spp, ours.seconds.back(), ours.error.back(),
               cycles.seconds.back(), cycles.error.back());
  }
  fmt::print("\nReferences: ours {} spp in {:.2f} s, Cycles {} spp in {:.2f} s.\n\n", reference_spp,
             ours_reference_seconds, reference_spp, cycles_seconds[std::to_string(reference_spp)].get<double>());

  fmt::print("| RMSE reached | ours s | Cycles s | Cycles / ours |\n|---:|---:|---:|---:|\n");
  for (size_t k = 0; k < cycles.error.size(); ++k) {
    const double target = cycles.error[k];
    const double a = seconds_to_reach(ours, target), b = seconds_to_reach(cycles, target);
    fmt::print("| {:.5f} | {:.3f} | {:.3f} | {:.2f} |\n", target, a, b, b / a);
  }
  const double mean_ours = mean(ours_reference), mean_cycles = mean(cycles_reference);
  fmt::print("\nConverged images: RMSE between them {:.5f} (mean pixel {:.5f} ours, {:.5f} Cycles, ratio {:.4f}).\n",
             rmse(ours_reference, cycles_reference), mean_ours, mean_cycles, mean_ours / mean_cycles);
  return 0;
}
