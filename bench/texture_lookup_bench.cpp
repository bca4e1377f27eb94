// The cost of one texture lookup: ours (bilinear, and trilinear from mip levels at a footprint of
// 8 texels) beside OpenImageIO's TextureSystem on the same 2048 x 2048 RGBA image at the same
// random UVs (its default bounded tile cache, mip-mapped by OIIO on the fly from the untiled PNG,
// bilinear at a zero footprint, trilinear at 8 texels). One thread, Google Benchmark's timing.
// The figures decide whether the renderer uses the TextureSystem (README, "Benchmarks").
#include <cstdint>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <OpenImageIO/texture.h>
#include <benchmark/benchmark.h>

#include "matrender/texture.h"

namespace {

constexpr int kSide = 2048;
constexpr size_t kLookups = 1 << 16;

// A 2048 x 2048 RGBA PNG of a smooth pattern, written once into the temporary folder.
const std::string& image_path() {
  static const std::string path = [] {
    const std::string file = (std::filesystem::temp_directory_path() / "matpredict_texture_lookup_bench.png").string();
    std::vector<uint8_t> pixels(static_cast<size_t>(kSide) * kSide * 4);
    for (size_t i = 0; i < pixels.size(); ++i) pixels[i] = static_cast<uint8_t>((i * 2654435761u) >> 24);
    auto out = OIIO::ImageOutput::create(file);
    out->open(file, OIIO::ImageSpec(kSide, kSide, 4, OIIO::TypeDesc::UINT8));
    out->write_image(OIIO::TypeDesc::UINT8, pixels.data());
    out->close();
    return file;
  }();
  return path;
}

const std::vector<float>& random_uvs() {
  static const std::vector<float> uvs = [] {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<float> v(2 * kLookups);
    for (float& x : v) x = unit(rng);
    return v;
  }();
  return uvs;
}

void ours(benchmark::State& state, float footprint_texels) {
  const matrender::TexturePtr texture = matrender::Texture::load(image_path(), matrender::ColorSpace::SRGB);
  const std::vector<float>& uv = random_uvs();
  const float footprint = footprint_texels / kSide;
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(texture->sample({uv[2 * i], uv[2 * i + 1]}, false, footprint));
    i = (i + 1) % kLookups;
  }
}

void oiio(benchmark::State& state, float footprint_texels) {
  OIIO::TextureSystem* system = OIIO::TextureSystem::create(false);
  const OIIO::ustring name(image_path());
  OIIO::TextureSystem::Perthread* thread = system->get_perthread_info();
  OIIO::TextureSystem::TextureHandle* handle = system->get_texture_handle(name, thread);
  OIIO::TextureOpt options;
  options.interpmode = OIIO::TextureOpt::InterpBilinear;
  options.mipmode = footprint_texels > 0.0f ? OIIO::TextureOpt::MipModeTrilinear : OIIO::TextureOpt::MipModeNoMIP;
  const std::vector<float>& uv = random_uvs();
  const float d = footprint_texels / kSide;
  float result[4];
  size_t i = 0;
  for (auto _ : state) {
    system->texture(handle, thread, options, uv[2 * i], 1.0f - uv[2 * i + 1], d, 0.0f, 0.0f, d, 4, result);
    benchmark::DoNotOptimize(result);
    i = (i + 1) % kLookups;
  }
  OIIO::TextureSystem::destroy(system);
}

}  // namespace

BENCHMARK_CAPTURE(ours, bilinear, 0.0f);
BENCHMARK_CAPTURE(ours, trilinear_8_texels, 8.0f);
BENCHMARK_CAPTURE(oiio, bilinear, 0.0f);
BENCHMARK_CAPTURE(oiio, trilinear_8_texels, 8.0f);
BENCHMARK_MAIN();
