// Concrete, stone, marble, ceramic, terracotta and plaster. Reflectances stay within their
// class's range (material_library.cpp); relief is in metres, at the tile's physical size
// (the style table's).
#include <cmath>

#include "matmaterial/library/periodic_noise.h"
#include "library/style_kit.h"
#include "library/styles.h"

namespace matmaterial::library {
namespace {

using P = MaterialParameter;

glm::dvec3 concrete_grey(matbase::UniformSource& random) {
  return pick_colour(random,
                     {from_srgb(0.62, 0.61, 0.58), from_srgb(0.50, 0.50, 0.50), from_srgb(0.70, 0.67, 0.62),
                      from_srgb(0.45, 0.46, 0.47)},
                     0.05);
}

// Thin veins where the warped phase k1 u + k2 v + warp crosses a whole number: |sin(pi phase)|
// has period 1 in the phase, so whole k1, k2 and a periodic warp keep the veins seamless.
struct Veins {
  int k1 = 1, k2 = 1;
  double sharpness = 12.0;
  uint32_t salt = 0;
  double at(glm::dvec2 uv) const {
    const double phase = k1 * uv.x + k2 * uv.y + 2.5 * fractal_noise(uv, {2, 2}, 5, salt);
    const double primary = std::pow(1.0 - std::abs(std::sin(kPi * phase)), sharpness);
    const double secondary = std::pow(1.0 - std::abs(std::sin(kPi * 3.0 * phase)), 3.0 * sharpness);
    return std::min(1.0, primary + 0.4 * secondary);
  }
};

Veins draw_veins(matbase::UniformSource& random) {
  Veins veins;
  veins.k1 = 1 + static_cast<int>(random.choice(3));
  veins.k2 = static_cast<int>(random.choice(3));
  veins.sharpness = random.between(8.0, 20.0);
  veins.salt = random.bits();
  return veins;
}

Recipe polished_marble(const glm::dvec3& ground, const glm::dvec3& vein_colour, const Veins& veins,
                       matbase::UniformSource& random) {
  const double roughness = random.between(0.05, 0.12);
  const uint32_t salt = random.bits();
  Recipe recipe;
  recipe.texel = [=](glm::dvec2 uv) {
    const double cloud = fractal_noise(uv, {3, 3}, 4, salt);
    Texel t;
    t.base_color = glm::mix(ground, vein_colour, 0.85 * veins.at(uv)) * (0.96 + 0.04 * cloud);
    t.roughness = roughness + 0.03 * cloud;
    return t;  // polished flat: no relief
  };
  return recipe;
}

}  // namespace

Recipe cast_concrete(matbase::UniformSource& random) {
  const glm::dvec3 grey = concrete_grey(random);
  const uint32_t salt = random.bits();
  Recipe recipe;
  recipe.texel = [=](glm::dvec2 uv) {
    const double speckle = fractal_noise(uv, {128, 128}, 2, salt);
    const double blotch = fractal_noise(uv, {4, 4}, 4, salt + 1u);
    const double pore = 1.0 - smoothstep(0.06, 0.12, cellular_noise(uv, {200, 200}, salt + 2u).f1);
    Texel t;
    t.base_color = grey * (0.85 + 0.2 * speckle) * (0.9 + 0.15 * blotch) * (1.0 - 0.4 * pore);
    t.roughness = 0.8 + 0.15 * speckle;
    t.height_m = 0.0015 * speckle - 0.002 * pore;
    return t;
  };
  return recipe;
}

Recipe aggregate_concrete(matbase::UniformSource& random) {
  const glm::dvec3 cement = concrete_grey(random);
  const glm::dvec3 stones[3] = {from_srgb(0.55, 0.50, 0.45), from_srgb(0.72, 0.70, 0.66), from_srgb(0.40, 0.38, 0.37)};
  const uint32_t salt = random.bits();
  const int pebbles = 50 + static_cast<int>(random.choice(30));
  Recipe recipe;
  recipe.texel = [=](glm::dvec2 uv) {
    const CellularSample cell = cellular_noise(uv, {pebbles, pebbles}, salt);
    const double stone = smoothstep(0.1, 0.2, cell.f2 - cell.f1);
    const glm::dvec3 pebble = stones[hash32(cell.cell) % 3] * (0.9 + 0.2 * hash_to_unit(cell.cell + 1u));
    const double grit = fractal_noise(uv, {256, 256}, 1, salt + 1u);
    Texel t;
    t.base_color = glm::mix(cement * (0.85 + 0.2 * grit), pebble, stone);
    t.roughness = glm::mix(0.9, 0.6, stone);
    t.height_m = 0.002 * stone + 0.0002 * grit;
    return t;
  };
  return recipe;
}

Recipe granite(matbase::UniformSource& random) {
  const glm::dvec3 feldspar = pick_colour(
      random, {from_srgb(0.80, 0.62, 0.58), from_srgb(0.85, 0.84, 0.80), from_srgb(0.70, 0.66, 0.62)}, 0.04);
  const glm::dvec3 quartz = from_srgb(0.62, 0.62, 0.64), mica = from_srgb(0.25, 0.25, 0.26);
  const double mica_share = random.between(0.1, 0.3);
  const double roughness = random.between(0.2, 0.3);
  const uint32_t salt = random.bits();
  Recipe recipe;
  recipe.texel = [=](glm::dvec2 uv) {
    const CellularSample grain = cellular_noise(uv, {90, 90}, salt);
    const double mineral = hash_to_unit(grain.cell);
    const glm::dvec3 colour = mineral < mica_share ? mica : (mineral < 0.6 ? feldspar : quartz);
    const double edge = 1.0 - smoothstep(0.0, 0.08, grain.f2 - grain.f1);
    Texel t;
    t.base_color = colour * (0.9 + 0.1 * hash_to_unit(grain.cell + 7u)) * (1.0 - 0.15 * edge);
    t.roughness = roughness + 0.05 * edge;
    t.height_m = -0.00003 * edge;
    return t;
  };
  return recipe;
}

Recipe slate(matbase::UniformSource& random) {
  const glm::dvec3 colour = pick_colour(
      random, {from_srgb(0.30, 0.32, 0.35), from_srgb(0.28, 0.30, 0.28), from_srgb(0.35, 0.33, 0.32)}, 0.06);
  const double roughness = random.between(0.6, 0.75);
  const uint32_t salt = random.bits();
  Recipe recipe;
  recipe.texel = [=](glm::dvec2 uv) {
    const double layers = fractal_noise(uv, {2, 16}, 5, salt);  // cleavage planes along u
    const double cleft = ridged_noise(uv, {3, 12}, 4, salt + 1u);
    Texel t;
    t.base_color = colour * (0.85 + 0.3 * layers);
    t.roughness = roughness + 0.1 * cleft;
    t.height_m = 0.003 * cleft;
    return t;
  };
  return recipe;
}

Recipe sandstone(matbase::UniformSource& random) {
  const glm::dvec3 colour = pick_colour(
      random, {from_srgb(0.78, 0.68, 0.52), from_srgb(0.72, 0.58, 0.45), from_srgb(0.82, 0.75, 0.62)}, 0.05);
  const int beds = 6 + static_cast<int>(random.choice(8));
  const uint32_t salt = random.bits();
  Recipe recipe;
  recipe.texel = [=](glm::dvec2 uv) {
    const double bedding = 0.5 + 0.5 * std::sin(2.0 * kPi * (beds * uv.y + fractal_noise(uv, {2, 2}, 3, salt)));
    const double grains = fractal_noise(uv, {256, 256}, 2, salt + 1u);
    Texel t;
    t.base_color = colour * (0.85 + 0.12 * bedding) * (0.92 + 0.16 * grains);
    t.roughness = 0.85 + 0.1 * grains;
    t.height_m = 0.0004 * grains;
    return t;
  };
  return recipe;
}

Recipe carrara_marble(matbase::UniformSource& random) {
  const glm::dvec3 ground = pick_colour(
      random, {from_srgb(0.90, 0.90, 0.88), from_srgb(0.86, 0.86, 0.86), from_srgb(0.92, 0.90, 0.86)}, 0.02);
  const Veins veins = draw_veins(random);
  return polished_marble(ground, from_srgb(0.45, 0.47, 0.50), veins, random);
}

Recipe nero_marble(matbase::UniformSource& random) {
  const glm::dvec3 ground = pick_colour(random, {from_srgb(0.22, 0.22, 0.23), from_srgb(0.24, 0.22, 0.21)}, 0.03);
  const Veins veins = draw_veins(random);
  return polished_marble(ground, from_srgb(0.85, 0.84, 0.80), veins, random);
}

Recipe glazed_ceramic(matbase::UniformSource& random) {
  const glm::dvec3 glaze = pick_colour(random,
                                       {from_srgb(0.93, 0.91, 0.86), from_srgb(0.78, 0.85, 0.76),
                                        from_srgb(0.60, 0.72, 0.85), from_srgb(0.85, 0.55, 0.40),
                                        from_srgb(0.35, 0.45, 0.60)},
                                       0.03);
  const double roughness = random.between(0.1, 0.2);
  const uint32_t salt = random.bits();
  Recipe recipe;
  recipe.texel = [=](glm::dvec2 uv) {
    const double mottling = fractal_noise(uv, {6, 6}, 4, salt);
    Texel t;
    t.base_color = glaze * (1.0 - 0.2 * mottling);
    t.roughness = roughness + 0.08 * mottling;
    t.height_m = 0.00005 * fractal_noise(uv, {48, 48}, 3, salt + 1u);  // orange peel
    return t;
  };
  recipe.constants = {{P::Clearcoat, glm::dvec3(1.0)},
                      {P::ClearcoatRoughness, glm::dvec3(random.between(0.02, 0.05))}};
  return recipe;
}

Recipe speckled_ceramic(matbase::UniformSource& random) {
  const glm::dvec3 body = pick_colour(random, {from_srgb(0.82, 0.76, 0.66), from_srgb(0.75, 0.72, 0.68)}, 0.03);
  const glm::dvec3 iron = from_srgb(0.30, 0.24, 0.20);
  const double roughness = random.between(0.25, 0.35);
  const uint32_t salt = random.bits();
  Recipe recipe;
  recipe.texel = [=](glm::dvec2 uv) {
    const double speck = 1.0 - smoothstep(0.04, 0.09, cellular_noise(uv, {120, 120}, salt).f1);
    Texel t;
    t.base_color = glm::mix(body * (0.95 + 0.05 * fractal_noise(uv, {5, 5}, 3, salt + 1u)), iron, speck);
    t.roughness = roughness;
    t.height_m = 0.00002 * fractal_noise(uv, {48, 48}, 3, salt + 2u);
    return t;
  };
  recipe.constants = {{P::Clearcoat, glm::dvec3(random.between(0.8, 1.0))},
                      {P::ClearcoatRoughness, glm::dvec3(random.between(0.03, 0.08))}};
  return recipe;
}

Recipe terracotta(matbase::UniformSource& random) {
  const glm::dvec3 clay = pick_colour(random,
                                      {from_srgb(0.72, 0.40, 0.28), from_srgb(0.66, 0.36, 0.26),
                                       from_srgb(0.78, 0.48, 0.34), from_srgb(0.60, 0.34, 0.27)},
                                      0.06);
  const uint32_t salt = random.bits();
  Recipe recipe;
  recipe.texel = [=](glm::dvec2 uv) {
    const double mottle = fractal_noise(uv, {5, 5}, 4, salt);
    const double pore = 1.0 - smoothstep(0.05, 0.1, cellular_noise(uv, {150, 150}, salt + 1u).f1);
    Texel t;
    t.base_color = clay * (0.85 + 0.25 * mottle) * (1.0 - 0.25 * pore);
    t.roughness = 0.85 + 0.1 * mottle;
    t.height_m = 0.0002 * fractal_noise(uv, {64, 64}, 3, salt + 2u) - 0.0005 * pore;
    return t;
  };
  return recipe;
}

Recipe trowelled_plaster(matbase::UniformSource& random) {
  const glm::dvec3 paint = pick_colour(random,
                                       {from_srgb(0.88, 0.86, 0.82), from_srgb(0.90, 0.89, 0.86),
                                        from_srgb(0.85, 0.83, 0.78), from_srgb(0.80, 0.84, 0.86)},
                                       0.02);
  const uint32_t salt = random.bits();
  Recipe recipe;
  recipe.texel = [=](glm::dvec2 uv) {
    const double trowel = ridged_noise(uv, {3, 3}, 4, salt);  // the trowel's overlapping sweeps
    const double fine = fractal_noise(uv, {128, 128}, 2, salt + 1u);
    Texel t;
    t.base_color = paint * (0.96 + 0.04 * trowel);
    t.roughness = 0.9 - 0.1 * trowel;
    t.height_m = 0.003 * trowel + 0.0003 * fine;
    return t;
  };
  return recipe;
}

}  // namespace matmaterial::library
