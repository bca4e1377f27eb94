// The texture cache's memory bound: a wall of planes, each with its own 4k PNG map (36 by
// default, "dozens of 4k maps"), rendered once per limit in this one run: at each --limits
// value, then unbounded. Each row gives the render's seconds, the most texel memory held at once (load
// and render), the levels dropped and made again, and the process's peak memory so far; the images must all be the same.
// The maps are written once into --folder and reused. Timings are only meaningful on an
// otherwise idle machine.
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <OpenImageIO/imageio.h>
#include <fmt/core.h>

#include "matbase/memory_limit.h"
#include "matrender/camera.h"
#include "matrender/render.h"
#include "matrender/scene.h"
#include "matrender/texture.h"
#include "matrender/texture_cache.h"

namespace fs = std::filesystem;

namespace {

// Map k: stripes and rings of a colour of its own, so every map differs and PNG compresses it
// well (the maps are written once).
void write_map(const fs::path& path, int k, int size) {
  std::vector<uint8_t> pixels(static_cast<size_t>(size) * size * 3);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const double r = std::hypot(x - size / 2, y - size / 2) / size;
      const bool ring = static_cast<int>(r * (8 + k)) % 2 == 0;
      const bool stripe = ((x + y) / (16 + 4 * k)) % 2 == 0;
      uint8_t* p = &pixels[(static_cast<size_t>(y) * size + x) * 3];
      p[0] = static_cast<uint8_t>(ring ? 200 : 40 + 5 * k);
      p[1] = static_cast<uint8_t>(stripe ? 180 : 60);
      p[2] = static_cast<uint8_t>((7 * k) % 256);
    }
  const fs::path temporary = path.string() + ".tmp.png";
  auto out = OIIO::ImageOutput::create(temporary.string());
  if (!out || !out->open(temporary.string(), OIIO::ImageSpec(size, size, 3, OIIO::TypeDesc::UINT8)) ||
      !out->write_image(OIIO::TypeDesc::UINT8, pixels.data()) || !out->close())
    throw std::runtime_error(temporary.string() + ": cannot write the map");
  fs::rename(temporary, path);
}

std::vector<std::string> ensure_maps(const fs::path& folder, int count, int size) {
  fs::create_directories(folder);
  std::vector<std::string> paths;
  for (int k = 0; k < count; ++k) {
    const fs::path path = folder / fmt::format("map_{}_{}.png", size, k);
    if (!fs::exists(path)) {
      fmt::print("writing {}\n", path.string());
      std::fflush(stdout);
      write_map(path, k, size);
    }
    paths.push_back(path.string());
  }
  return paths;
}

// A square plane of side 1 m centred at (x, 0, z), facing -Y (the camera).
matgeom::TriangleMesh plane_at(float x, float z) {
  matgeom::TriangleMesh m;
  m.positions = {{x - 0.5f, 0, z - 0.5f}, {x + 0.5f, 0, z - 0.5f}, {x + 0.5f, 0, z + 0.5f}, {x - 0.5f, 0, z + 0.5f}};
  m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  m.triangles = {{0, 2, 1}, {0, 3, 2}};
  return m;
}

struct Run {
  double load_seconds = 0.0, render_seconds = 0.0;
  matrender::TextureCacheStats cache;
  std::vector<float> color;
};

Run render_wall(const std::vector<std::string>& maps, uint64_t limit_bytes, int resolution, int spp) {
  matrender::set_texture_memory_limit(limit_bytes);
  matrender::reset_texture_cache_counters();
  Run run;
  const auto start = std::chrono::steady_clock::now();
  matrender::Scene scene;
  const int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(maps.size()))));
  for (size_t k = 0; k < maps.size(); ++k) {
    matrender::Material m;
    m[matrender::MaterialParameter::BaseColor] = {glm::vec3(1.0f),
                                                  matrender::Texture::load(maps[k], matmaterial::ColorSpace::SRGB), 0};
    const float x = 1.1f * (static_cast<float>(k % side) - 0.5f * (side - 1));
    const float z = 1.1f * (static_cast<float>(k / side) - 0.5f * (side - 1));
    scene.add_mesh(plane_at(x, z), {scene.add_material(m)});
  }
  scene.add_lamp(matrender::PointLamp{glm::dvec3(0.0, -4.0, 2.0), 3000.0, glm::dvec3(1.0)});
  scene.set_background(glm::vec3(0.2f));
  run.load_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  matrender::RenderSettings settings;
  settings.samples_per_pixel = spp;
  settings.aovs = 0;  // colour only
  const double distance = 0.62 * 1.1 * side / std::tan(0.5 * 0.8);
  const matrender::Camera camera =
      matrender::Camera::look_at({0.0, -distance, 0.0}, {0.0, 0.0, 0.0}, {0, 0, 1}, 0.8, resolution, resolution);
  matrender::FrameBuffers frame;
  run.render_seconds = matrender::render(scene, camera, settings, frame).seconds;
  run.cache = matrender::texture_cache_stats();
  run.color = frame.color;
  return run;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Renders a wall of planes with a 4k map each, unbounded and under texture memory limits"};
  int maps = 36, size = 4096, resolution = 512, spp = 16;
  std::vector<uint64_t> limits_mib = {1024, 256};
  std::string folder = "texture_cache_maps";
  app.add_option("--maps", maps, "how many maps (and planes)")->capture_default_str()->check(CLI::Range(1, 400));
  app.add_option("--size", size, "side of each map in texels")->capture_default_str()->check(CLI::Range(16, 16384));
  app.add_option("--resolution", resolution, "image side in pixels")->capture_default_str()->check(CLI::Range(8, 4096));
  app.add_option("--spp", spp, "samples per pixel")->capture_default_str()->check(CLI::Range(1, 4096));
  app.add_option("--limits", limits_mib, "texture memory limits to run at, MiB")->capture_default_str();
  app.add_option("--folder", folder, "where the maps are written once and reused")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    const std::vector<std::string> paths = ensure_maps(folder, maps, size);
    fmt::print("{} maps of {}x{} (8-bit RGB, kept as RGBA bytes: {} each at level 0), {}x{} at {} spp\n", maps, size,
               size, matbase::byte_size_text(4.0 * size * size), resolution, resolution, spp);
    // Bounded runs first, so that the process's peak resident memory after each says what it took.
    fmt::print("| limit | load s | render s | texels held at most | levels dropped | made again | process peak RSS so far |\n");
    fmt::print("|---|---:|---:|---:|---:|---:|---:|\n");
    limits_mib.push_back(0);
    std::vector<std::vector<float>> images;
    for (const uint64_t mib : limits_mib) {
      const Run run = render_wall(paths, mib << 20, resolution, spp);
      images.push_back(run.color);
      rusage usage{};
      getrusage(RUSAGE_SELF, &usage);
      fmt::print("| {} | {:.2f} | {:.2f} | {} | {} | {} | {} |\n",
                 mib == 0 ? "none (default " + matbase::byte_size_text(static_cast<double>(run.cache.limit_bytes)) + ")"
                          : matbase::byte_size_text(static_cast<double>(mib << 20)),
                 run.load_seconds, run.render_seconds, matbase::byte_size_text(static_cast<double>(run.cache.peak_bytes)),
                 run.cache.evictions, run.cache.reloads,
                 matbase::byte_size_text(static_cast<double>(usage.ru_maxrss) * 1024.0));
      std::fflush(stdout);
    }
    bool same = true;
    for (const std::vector<float>& image : images) same = same && image == images.back();
    fmt::print("images under every limit {} the unbounded one\n", same ? "are bit for bit" : "DIFFER from");
    if (!same) return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "texture_cache_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
