#include "builtin/procedural_textures.h"

#include "matbase/image/srgb.h"
#include "matbase/image/unorm.h"
#include "matbase/smoothstep.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace matgeom::builtin {
namespace {

double lerp(double a, double b, double t) { return a + (b - a) * t; }

double lattice_value(int ix, int iy, int period_x, int period_y, uint32_t salt) {
  const int wx = ((ix % period_x) + period_x) % period_x;
  const int wy = ((iy % period_y) + period_y) % period_y;
  return hash_to_unit(hash32(salt ^ static_cast<uint32_t>(wx)) + static_cast<uint32_t>(wy) * 0x9e3779b9u);
}

}  // namespace

double periodic_value_noise(double x, double y, int period_x, int period_y, uint32_t salt) {
  const double px = x * period_x, py = y * period_y;
  const int ix = static_cast<int>(std::floor(px)), iy = static_cast<int>(std::floor(py));
  const double fx = matbase::smoothstep(px - ix), fy = matbase::smoothstep(py - iy);
  const auto value = [&](int dx, int dy) { return lattice_value(ix + dx, iy + dy, period_x, period_y, salt); };
  return lerp(lerp(value(0, 0), value(1, 0), fx), lerp(value(0, 1), value(1, 1), fx), fy);
}

double periodic_value_noise(double x, double y, int period, uint32_t salt) {
  return periodic_value_noise(x, y, period, period, salt);
}

double fractal_noise(double x, double y, int base_period_x, int base_period_y, uint32_t salt) {
  double sum = 0.0, amplitude = 0.5, total = 0.0;
  for (int octave = 0; octave < 4; ++octave) {
    sum += amplitude * periodic_value_noise(x, y, base_period_x << octave, base_period_y << octave,
                                            salt + 977u * static_cast<uint32_t>(octave));
    total += amplitude;
    amplitude *= 0.5;
  }
  return sum / total;
}

double fractal_noise(double x, double y, int base_period, uint32_t salt) {
  return fractal_noise(x, y, base_period, base_period, salt);
}

matbase::ImagePixels rgb_image(std::string name, int size, const std::function<glm::dvec3(double, double)>& texel) {
  matbase::ImagePixels image;
  image.name = std::move(name);
  image.width = image.height = size;
  image.channels = 3;
  image.data.reserve(static_cast<size_t>(size) * static_cast<size_t>(size) * 3);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const glm::dvec3 rgb = texel((x + 0.5) / size, 1.0 - (y + 0.5) / size);
      for (int c = 0; c < 3; ++c) image.data.push_back(matbase::unorm8(rgb[c]));
    }
  return image;
}

matbase::ImagePixels normal_map_image(std::string name, int size, const std::function<double(double, double)>& height,
                             double bump) {
  std::vector<double> h(static_cast<size_t>(size) * static_cast<size_t>(size));
  const auto at = [&](int x, int y) -> double& {
    const int wx = (x + size) % size, wy = (y + size) % size;
    return h[static_cast<size_t>(wy) * static_cast<size_t>(size) + static_cast<size_t>(wx)];
  };
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) at(x, y) = height((x + 0.5) / size, 1.0 - (y + 0.5) / size);
  return rgb_image(std::move(name), size, [&](double u, double v) {
    const int x = static_cast<int>(u * size), y = static_cast<int>((1.0 - v) * size);
    const double dh_du = 0.5 * (at(x + 1, y) - at(x - 1, y));
    const double dh_dv = 0.5 * (at(x, y - 1) - at(x, y + 1));  // rows grow downward, v upward
    const glm::dvec3 n = glm::normalize(glm::dvec3(-bump * dh_du, -bump * dh_dv, 1.0));
    return 0.5 * n + 0.5;
  });
}

}  // namespace matgeom::builtin
