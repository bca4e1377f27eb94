#pragma once
// Noise that tiles: every function here is periodic over the unit square, so a map rasterised
// from it continues across its edges (docs/material_library.md, "Seamless maps"). Periods are
// whole numbers of lattice cells across the tile; octaves double them, which keeps them whole.
// Everything is a pure function of its arguments (hashes, no state), so maps come out the same
// whatever the thread count.
#include <cstdint>

#include <glm/glm.hpp>

namespace matmaterial::library {

// MurmurHash3's 32-bit finalizer, and its top 24 bits scaled into [0, 1).
uint32_t hash32(uint32_t x);
double hash_to_unit(uint32_t x);
// A hash of a wrapped lattice point and a salt.
uint32_t lattice_hash(int ix, int iy, glm::ivec2 period, uint32_t salt);

// How value noise blends its lattice. The library's materials use Perlin's quintic fade (C2, so
// their normals have no creases at cell borders) between corners hashed twice. The built-in
// vase's glaze (matgeom) was drawn with the cubic smoothstep between corners hashed once, and
// keeps that so its images stay what they were.
enum class ValueNoiseBlend { Quintic, CubicOnceHashed };

// Value noise in [0, 1] on a lattice of period.x x period.y cells across the tile.
double value_noise(glm::dvec2 uv, glm::ivec2 period, uint32_t salt,
                   ValueNoiseBlend blend = ValueNoiseBlend::Quintic);

// `octaves` octaves of value noise from `base_period` cells up, halving in amplitude, normalised
// back into [0, 1]. Unequal periods along u and v stretch it into streaks.
double fractal_noise(glm::dvec2 uv, glm::ivec2 base_period, int octaves, uint32_t salt,
                     ValueNoiseBlend blend = ValueNoiseBlend::Quintic);

// The same folded about its middle: 1 - |2n - 1| per octave, ridges along the zero crossings
// (Musgrave's ridged multifractal, without the spectral weighting), in [0, 1].
double ridged_noise(glm::dvec2 uv, glm::ivec2 base_period, int octaves, uint32_t salt);

// Worley's cellular noise: one feature point jittered inside every lattice cell; f1 and f2 are
// the distances, in cell widths, to the nearest and second nearest, `cell` hashes the nearest's
// cell (for a colour per grain or pebble).
struct CellularSample {
  double f1 = 0.0;
  double f2 = 0.0;
  uint32_t cell = 0;
};
CellularSample cellular_noise(glm::dvec2 uv, glm::ivec2 period, uint32_t salt);

}  // namespace matmaterial::library
