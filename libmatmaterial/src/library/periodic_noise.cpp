#include "matmaterial/library/periodic_noise.h"

#include <algorithm>
#include <cmath>

#include "matbase/smoothstep.h"

namespace matmaterial::library {
namespace {

int wrap(int i, int period) { return ((i % period) + period) % period; }

// Perlin's improved fade 6t^5 - 15t^4 + 10t^3: zero first and second derivatives at 0 and 1.
double quintic(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

// a + (b - a) t, which rounds differently from glm::mix's a (1 - t) + b t.
double lerp(double a, double b, double t) { return a + (b - a) * t; }

// A wrapped lattice point and a salt, mixed once; lattice_hash mixes it again.
uint32_t lattice_key(int ix, int iy, glm::ivec2 period, uint32_t salt) {
  const auto wx = static_cast<uint32_t>(wrap(ix, period.x)), wy = static_cast<uint32_t>(wrap(iy, period.y));
  return hash32(salt ^ wx) + wy * 0x9e3779b9u;
}

}  // namespace

uint32_t hash32(uint32_t x) {
  x ^= x >> 16;
  x *= 0x85ebca6bu;
  x ^= x >> 13;
  x *= 0xc2b2ae35u;
  x ^= x >> 16;
  return x;
}

double hash_to_unit(uint32_t x) { return static_cast<double>(hash32(x) >> 8) * (1.0 / 16777216.0); }

uint32_t lattice_hash(int ix, int iy, glm::ivec2 period, uint32_t salt) { return hash32(lattice_key(ix, iy, period, salt)); }

double value_noise(glm::dvec2 uv, glm::ivec2 period, uint32_t salt, ValueNoiseBlend blend) {
  const glm::dvec2 p = uv * glm::dvec2(period);
  const int ix = static_cast<int>(std::floor(p.x)), iy = static_cast<int>(std::floor(p.y));
  const glm::dvec2 t(p.x - ix, p.y - iy);
  if (blend == ValueNoiseBlend::CubicOnceHashed) {
    const auto corner = [&](int dx, int dy) { return hash_to_unit(lattice_key(ix + dx, iy + dy, period, salt)); };
    const double fx = matbase::smoothstep(t.x), fy = matbase::smoothstep(t.y);
    return lerp(lerp(corner(0, 0), corner(1, 0), fx), lerp(corner(0, 1), corner(1, 1), fx), fy);
  }
  const auto corner = [&](int dx, int dy) { return hash_to_unit(lattice_hash(ix + dx, iy + dy, period, salt)); };
  const double fx = quintic(t.x), fy = quintic(t.y);
  const double bottom = glm::mix(corner(0, 0), corner(1, 0), fx);
  const double top = glm::mix(corner(0, 1), corner(1, 1), fx);
  return glm::mix(bottom, top, fy);
}

double fractal_noise(glm::dvec2 uv, glm::ivec2 base_period, int octaves, uint32_t salt, ValueNoiseBlend blend) {
  double sum = 0.0, amplitude = 1.0, total = 0.0;
  for (int octave = 0; octave < octaves; ++octave) {
    sum += amplitude * value_noise(uv, base_period << octave, salt + 977u * static_cast<uint32_t>(octave), blend);
    total += amplitude;
    amplitude *= 0.5;
  }
  return sum / total;
}

double ridged_noise(glm::dvec2 uv, glm::ivec2 base_period, int octaves, uint32_t salt) {
  double sum = 0.0, amplitude = 1.0, total = 0.0;
  for (int octave = 0; octave < octaves; ++octave) {
    const double n = value_noise(uv, base_period << octave, salt + 7919u * static_cast<uint32_t>(octave));
    sum += amplitude * (1.0 - std::abs(2.0 * n - 1.0));
    total += amplitude;
    amplitude *= 0.5;
  }
  return sum / total;
}

CellularSample cellular_noise(glm::dvec2 uv, glm::ivec2 period, uint32_t salt) {
  const glm::dvec2 p = uv * glm::dvec2(period);
  const int ix = static_cast<int>(std::floor(p.x)), iy = static_cast<int>(std::floor(p.y));
  CellularSample sample{1e9, 1e9, 0};
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const uint32_t h = lattice_hash(ix + dx, iy + dy, period, salt);
      const glm::dvec2 feature(ix + dx + hash_to_unit(h), iy + dy + hash_to_unit(h ^ 0x5bd1e995u));
      const double d = glm::length(feature - p);
      if (d < sample.f1) {
        sample.f2 = sample.f1;
        sample.f1 = d;
        sample.cell = h;
      } else if (d < sample.f2) {
        sample.f2 = d;
      }
    }
  return sample;
}

}  // namespace matmaterial::library
