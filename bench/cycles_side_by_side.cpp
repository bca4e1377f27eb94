// Blender 3.4 Cycles beside libmatrender on the same scenes, in one run: the bumpy sphere of
// render_bench with a fine checker as its base colour under the paper's rig ("rig"), the same
// sphere in smooth glass tinted by the checker under the rig ("glass"), and the textured sphere
// lit by an environment map with a small bright sun ("environment"). Each is rendered by both at
// the same sample counts and threads, and by us also with uniform light selection (Cycles 3.4's)
// and without mip-mapping, to show what each technique buys. Prints each render's time and
// error against its own converged reference (uniform selection converges to the default's
// image, no mip-mapping to its own), the time each needs to reach Cycles' errors, and how far
// the converged images are apart. Needs Debian's `blender` (3.4) on PATH or --blender; Blender
// is a reference here, never a dependency of the product.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <OpenImageIO/imageio.h>

#include "bench_scenes.h"
#include "image_error.h"
#include "matbase/pi.h"
#include "matrender/paper_setup.h"
#include "matrender/render.h"
#include "matrender/rig_lamps.h"
#include "matrender/texture.h"
#include "shaders_ref/cycles_reference.h"

namespace fs = std::filesystem;

namespace {

void write_image(const std::string& path, int width, int height, int channels, OIIO::TypeDesc type,
                 const void* pixels) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out || !out->open(path, OIIO::ImageSpec(width, height, channels, type)) || !out->write_image(type, pixels) ||
      !out->close())
    throw std::runtime_error(path + ": cannot write");
}

// A 2048 x 2048 sRGB checker of 4-texel squares: finer than a pixel where the sphere is seen,
// the case mip-mapping is for.
std::string write_checker(const std::string& folder) {
  constexpr int kSize = 2048;
  std::vector<uint8_t> pixels(static_cast<size_t>(kSize) * kSize * 3);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const bool light = ((x / 4) + (y / 4)) % 2 == 0;
      uint8_t* p = &pixels[(static_cast<size_t>(y) * kSize + x) * 3];
      p[0] = light ? 230 : 60;
      p[1] = light ? 200 : 40;
      p[2] = light ? 150 : 30;
    }
  const std::string path = fs::absolute(fs::path(folder) / "checker.png").string();
  write_image(path, kSize, kSize, 3, OIIO::TypeDesc::UINT8, pixels.data());
  return path;
}

// A 512 x 256 equirectangular sky: blue above, brown below the horizon, and a sun of radius 2
// degrees, 2000 times brighter than the sky, 40 degrees up.
std::string write_sky(const std::string& folder) {
  constexpr int kWidth = 512, kHeight = 256;
  std::vector<float> pixels(static_cast<size_t>(kWidth) * kHeight * 3);
  const double pi = matbase::kPi;
  const glm::dvec3 sun = glm::normalize(glm::dvec3(std::cos(0.7), 0.3, std::sin(0.7)));
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      // Cycles' convention: u = 0.5 - atan2(dy, dx) / 2 pi, v = 1 - acos(dz) / pi (row 0 on top).
      const double u = (x + 0.5) / kWidth, v = 1.0 - (y + 0.5) / kHeight;
      const double phi = (0.5 - u) * 2.0 * pi, theta = (1.0 - v) * pi;
      const glm::dvec3 d(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
      glm::dvec3 c = d.z > 0.0 ? glm::mix(glm::dvec3(0.6, 0.7, 0.9), glm::dvec3(0.2, 0.35, 0.8), d.z)
                               : glm::dvec3(0.25, 0.2, 0.15);
      if (glm::dot(d, sun) > std::cos(2.0 * pi / 180.0)) c = glm::dvec3(2000.0, 1800.0, 1500.0);
      for (int k = 0; k < 3; ++k) pixels[(static_cast<size_t>(y) * kWidth + x) * 3 + k] = static_cast<float>(c[k]);
    }
  const std::string path = fs::absolute(fs::path(folder) / "sky.exr").string();
  write_image(path, kWidth, kHeight, 3, OIIO::TypeDesc::FLOAT, pixels.data());
  return path;
}

shaders_ref::CyclesScene make_scene(const std::string& name, size_t triangles, int resolution,
                                    const std::string& checker, const std::string& sky) {
  shaders_ref::CyclesScene scene;
  scene.mesh = bench::displaced_sphere(triangles);
  scene.material = bench::bench_material();
  scene.material[matrender::MaterialParameter::BaseColor] = {
      glm::vec3(1.0f), matrender::Texture::load(checker, matmaterial::ColorSpace::SRGB), 0};
  scene.camera = matrender::paper_view(scene.mesh, resolution, resolution);
  if (name == "glass") {
    scene.material.set(matrender::MaterialParameter::Transmission, 1.0f);
    scene.material.set(matrender::MaterialParameter::Roughness, 0.0f);
    scene.material.set(matrender::MaterialParameter::Ior, 1.5f);
    scene.background = glm::vec3(0.05f);
  }
  if (name == "environment") {
    scene.environment = shaders_ref::CyclesEnvironment{sky, 1.0, 0.0};
  } else {
    scene.lamps = matrender::rig_lamps(matrender::paper_rig(scene.mesh));
  }
  return scene;
}

// Ours, as the scene is for Cycles, with these settings' light selection and mip-mapping.
matrender::Scene our_scene(const shaders_ref::CyclesScene& description) {
  matrender::Scene scene;
  scene.add_mesh(description.mesh, {scene.add_material(description.material)});
  for (const matrender::Lamp& lamp : description.lamps) scene.add_lamp(lamp);
  if (description.environment)
    scene.set_background(matrender::EnvironmentMap{
        matrender::Texture::load(description.environment->exr_path, matmaterial::ColorSpace::NonColor),
        static_cast<float>(description.environment->strength), static_cast<float>(description.environment->rotation_z)});
  else
    scene.set_background(description.background);
  scene.commit();
  return scene;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"cycles_side_by_side: libmatrender beside Blender 3.4 Cycles, time to the same error"};
  size_t triangles = 10'000;
  int resolution = 256, threads = 2, reference_spp = 1024;
  std::vector<int> spp_list = {1, 4, 16, 64, 256};
  std::vector<std::string> scene_names = {"rig", "glass", "environment"};
  std::string blender = "blender", work = "cycles_side_by_side_out";
  app.add_option("--scenes", scene_names, "scenes to run: rig, glass, environment")
      ->check(CLI::IsMember({"rig", "glass", "environment"}))
      ->capture_default_str();
  app.add_option("--triangles", triangles, "triangles of the bumpy sphere")->capture_default_str();
  app.add_option("--resolution", resolution, "image side in pixels")->capture_default_str()->check(CLI::Range(8, 4096));
  app.add_option("--threads", threads, "threads for both renderers")->capture_default_str()->check(CLI::Range(1, 256));
  app.add_option("--spp", spp_list, "sample counts to time")->capture_default_str()->check(CLI::Range(1, 1 << 20));
  app.add_option("--reference-spp", reference_spp, "samples of each converged reference")
      ->capture_default_str()
      ->check(CLI::Range(1, 1 << 20));
  app.add_option("--blender", blender, "Blender 3.4 executable")->capture_default_str();
  app.add_option("--work", work, "folder for the scene descriptions, the images and Cycles' EXRs")
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  std::sort(spp_list.begin(), spp_list.end());
  try {
    fs::create_directories(work);
    const std::string checker = write_checker(work), sky = write_sky(work);
    for (const std::string& name : scene_names) {
      const shaders_ref::CyclesScene description = make_scene(name, triangles, resolution, checker, sky);
      // Cycles first, alone on the machine; its reference is rendered last.
      std::vector<shaders_ref::CyclesRender> cycles_renders;
      for (const int spp : spp_list) cycles_renders.push_back({spp, 0});
      cycles_renders.push_back({reference_spp, 0});
      fmt::print(stderr, "{}: rendering with Blender into {} ...\n", name, work + "/" + name);
      shaders_ref::render_with_cycles(description, cycles_renders, threads, work + "/" + name, blender);
      const std::vector<float> cycles_reference =
          shaders_ref::read_rgb_exr(cycles_renders.back().exr_path, resolution, resolution);

      matrender::Scene scene = our_scene(description);
      struct Variant {
        std::string label;
        matrender::LightSelection selection;
        bool mipmaps;
      };
      const std::vector<Variant> variants = {{"ours", matrender::LightSelection::Importance, true},
                                             {"uniform selection", matrender::LightSelection::Uniform, true},
                                             {"no mip-mapping", matrender::LightSelection::Importance, false}};
      const auto render_ours = [&](const Variant& v, int spp, double* seconds) {
        matrender::RenderSettings settings;
        settings.samples_per_pixel = spp;
        settings.threads = threads;
        settings.aovs = 0;
        settings.light_selection = v.selection;
        settings.mipmaps = v.mipmaps;
        matrender::FrameBuffers frame;
        *seconds = matrender::render(scene, description.camera, settings, frame).seconds + scene.bvh_build_seconds();
        return frame.color;
      };
      double unused;
      const std::vector<float> reference = render_ours(variants[0], reference_spp, &unused);
      const std::vector<float> reference_without_mipmaps = render_ours(variants[2], reference_spp, &unused);

      std::vector<bench::Curve> curves(variants.size() + 1);  // ours, uniform, no mip-mapping, Cycles
      for (size_t k = 0; k < spp_list.size(); ++k) {
        for (size_t v = 0; v < variants.size(); ++v) {
          double seconds;
          const std::vector<float> image = render_ours(variants[v], spp_list[k], &seconds);
          curves[v].seconds.push_back(seconds);
          curves[v].error.push_back(bench::rmse(image, variants[v].mipmaps ? reference : reference_without_mipmaps));
        }
        curves.back().seconds.push_back(cycles_renders[k].seconds);
        curves.back().error.push_back(bench::rmse(
            shaders_ref::read_rgb_exr(cycles_renders[k].exr_path, resolution, resolution), cycles_reference));
      }

      fmt::print("## {}: bumpy sphere ({} triangles), {}x{}, {} threads\n\n", name, description.mesh.triangle_count(),
                 resolution, resolution, threads);
      fmt::print("| spp | ours s | RMSE | uniform selection s | RMSE | no mip-mapping s | RMSE | Cycles s | RMSE |\n");
      fmt::print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
      for (size_t k = 0; k < spp_list.size(); ++k) {
        fmt::print("| {} ", spp_list[k]);
        for (const bench::Curve& c : curves) fmt::print("| {:.3f} | {:.5f} ", c.seconds[k], c.error[k]);
        fmt::print("|\n");
      }
      fmt::print("\nSeconds to reach Cycles' errors (interpolated log-log):\n\n");
      fmt::print("| RMSE | ours s | uniform selection / ours | no mip-mapping / ours | Cycles s | Cycles / ours |\n");
      fmt::print("|---:|---:|---:|---:|---:|---:|\n");
      for (const double target : curves.back().error) {
        const double ours = bench::seconds_to_reach(curves[0], target);
        const double cycles = bench::seconds_to_reach(curves[3], target);
        fmt::print("| {:.5f} | {:.3f} | {:.2f} | {:.2f} | {:.3f} | {:.2f} |\n", target, ours,
                   bench::seconds_to_reach(curves[1], target) / ours, bench::seconds_to_reach(curves[2], target) / ours,
                   cycles, cycles / ours);
      }
      fmt::print("\nConverged ({} spp): ours without mip-mapping against Cycles RMSE {:.5f}, mean pixel ratio {:.4f}; "
                 "ours with mip-mapping against without RMSE {:.5f}.\n\n",
                 reference_spp, bench::rmse(reference_without_mipmaps, cycles_reference),
                 bench::mean(reference_without_mipmaps) / bench::mean(cycles_reference),
                 bench::rmse(reference, reference_without_mipmaps));
      std::fflush(stdout);
    }
  } catch (const std::exception& error) {
    fmt::print(stderr, "cycles_side_by_side: {}\n", error.what());
    return 1;
  }
  return 0;
}
