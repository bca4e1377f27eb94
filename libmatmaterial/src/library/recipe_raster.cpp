#include "library/recipe_raster.h"

#include <algorithm>
#include <array>
#include <exception>
#include <limits>
#include <thread>
#include <vector>

#include "matbase/cancellation.h"
#include "matbase/image/srgb.h"
#include "matbase/image/unorm.h"
#include "matbase/threads.h"
#include "matmaterial/library/height_normals.h"

namespace matmaterial::library {
namespace {

// Runs row(y) for every y in [0, rows) on `threads` threads, rows interleaved; rethrows the
// first exception a row threw, Cancelled among them.
template <class RowFunction>
void for_each_row(int rows, int threads, const std::atomic<bool>* cancel, const RowFunction& row) {
  std::vector<std::exception_ptr> errors(static_cast<size_t>(threads));
  const auto work = [&](int worker) {
    try {
      for (int y = worker; y < rows; y += threads) {
        matbase::throw_if_cancelled(cancel);
        row(y);
      }
    } catch (...) {
      errors[static_cast<size_t>(worker)] = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  for (int worker = 1; worker < threads; ++worker) pool.emplace_back(work, worker);
  work(0);
  for (std::thread& thread : pool) thread.join();
  for (const std::exception_ptr& error : errors)
    if (error) std::rethrow_exception(error);
}

// Whether every texel of a map held the first texel's value, and that value.
struct Uniformity {
  bool uniform = true;
  glm::dvec3 value{0.0};
  void see(const glm::dvec3& v, bool first) {
    if (first) value = v;
    else if (v != value) uniform = false;
  }
};

}  // namespace

FolderMaterial rasterise_recipe(const Recipe& recipe, const std::string& name, MaterialClass material_class,
                                double tile_size_m, int resolution, int threads, const std::atomic<bool>* cancel) {
  using P = MaterialParameter;
  const int workers = matbase::worker_threads(threads);
  const size_t texels = static_cast<size_t>(resolution) * static_cast<size_t>(resolution);
  matbase::ImagePixels base_color = matbase::blank_image(name + "#basecolor", resolution, resolution, 3);
  matbase::ImagePixels roughness = matbase::blank_image(name + "#roughness", resolution, resolution, 1);
  matbase::ImagePixels metallic = matbase::blank_image(name + "#metallic", resolution, resolution, 1);
  matbase::ImagePixels opacity = matbase::blank_image(name + "#opacity", resolution, resolution, 1);
  std::vector<double> height(texels);
  // Per row, so threads never share one: base colour, roughness, metallic, opacity, height.
  std::vector<std::array<Uniformity, 5>> row_uniformity(static_cast<size_t>(resolution));

  for_each_row(resolution, workers, cancel, [&](int y) {
    std::array<Uniformity, 5>& uniformity = row_uniformity[static_cast<size_t>(y)];
    for (int x = 0; x < resolution; ++x) {
      const glm::dvec2 uv((x + 0.5) / resolution, 1.0 - (y + 0.5) / resolution);
      const Texel t = recipe.texel(uv);
      const size_t i = static_cast<size_t>(y) * static_cast<size_t>(resolution) + static_cast<size_t>(x);
      for (int c = 0; c < 3; ++c)
        base_color.data[3 * i + static_cast<size_t>(c)] = matbase::unorm8(matbase::linear_to_srgb(t.base_color[c]));
      roughness.data[i] = matbase::unorm8(t.roughness);
      metallic.data[i] = matbase::unorm8(t.metallic);
      opacity.data[i] = matbase::unorm8(t.opacity);
      height[i] = t.height_m;
      const bool first = x == 0;
      uniformity[0].see(t.base_color, first);
      uniformity[1].see(glm::dvec3(t.roughness), first);
      uniformity[2].see(glm::dvec3(t.metallic), first);
      uniformity[3].see(glm::dvec3(t.opacity), first);
      uniformity[4].see(glm::dvec3(t.height_m), first);
    }
  });
  std::array<Uniformity, 5> uniformity = row_uniformity[0];
  for (const auto& row : row_uniformity)
    for (size_t m = 0; m < uniformity.size(); ++m)
      if (!row[m].uniform || row[m].value != uniformity[m].value) uniformity[m].uniform = false;

  FolderMaterial result;
  result.material = MaterialInputs(name);
  result.material_class = material_class;
  result.material.label_id = label_id(material_class);
  result.tile_size_m = tile_size_m;
  const auto map_or_constant = [&](P parameter, matbase::ImagePixels& image, const Uniformity& u) {
    if (u.uniform) {
      result.material.set(parameter, u.value);
      return;
    }
    result.material.set(parameter, 1.0).set_image(parameter, static_cast<int>(result.images.size()));
    result.images.push_back(std::move(image));
  };
  map_or_constant(P::BaseColor, base_color, uniformity[0]);
  map_or_constant(P::Roughness, roughness, uniformity[1]);
  map_or_constant(P::Metallic, metallic, uniformity[2]);
  map_or_constant(P::Alpha, opacity, uniformity[3]);

  if (!uniformity[4].uniform) {
    // Named values, not a structured binding: C++17 lambdas cannot capture one (clang refuses).
    const auto extremes = std::minmax_element(height.begin(), height.end());
    const double low = *extremes.first, span = *extremes.second - low;
    matbase::ImagePixels height_map = matbase::blank_image(name + "#height", resolution, resolution, 1);
    matbase::ImagePixels normal_map = matbase::blank_image(name + "#normal", resolution, resolution, 3);
    const double texel_m = tile_size_m / resolution;
    for_each_row(resolution, workers, cancel, [&](int y) {
      const size_t row = static_cast<size_t>(y) * static_cast<size_t>(resolution);
      for (size_t i = row; i < row + static_cast<size_t>(resolution); ++i)
        height_map.data[i] = matbase::unorm8((height[i] - low) / span);
      normal_map_row(height, resolution, texel_m, y, &normal_map.data[3 * row]);
    });
    result.material.normal_image = static_cast<int>(result.images.size());
    result.images.push_back(std::move(normal_map));
    result.height_image = static_cast<int>(result.images.size());
    result.images.push_back(std::move(height_map));
  }
  for (const auto& [parameter, value] : recipe.constants) result.material.set(parameter, value);
  return result;
}

}  // namespace matmaterial::library
