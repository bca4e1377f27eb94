// Wood, fabric, leather and paper. Reflectances stay within their class's range
// (material_library.cpp); relief is in metres, at the tile's physical size
// (the style table's).
#include <algorithm>
#include <cmath>

#include "matmaterial/library/periodic_noise.h"
#include "library/style_kit.h"
#include "library/styles.h"

namespace matmaterial::library {
namespace {

using P = MaterialParameter;

// Growth rings across v (the grain runs along u), warped by noise, and pores as streaks along
// the grain.
struct WoodGrain {
  glm::dvec3 earlywood, latewood;
  int rings = 20;  // per tile: whole, so the rings wrap
  uint32_t salt = 0;

  // 0 in the pale earlywood, 1 in the dark latewood band.
  double latewood_band(glm::dvec2 uv) const {
    const double warp = 1.2 * fractal_noise(uv, {1, 2}, 4, salt) + 0.3 * fractal_noise(uv, {4, 8}, 3, salt + 1u);
    const double t = fract(rings * uv.y + warp);
    return smoothstep(0.55, 0.8, t) * (1.0 - smoothstep(0.9, 1.0, t));
  }
  double pores(glm::dvec2 uv) const { return smoothstep(0.55, 0.8, fractal_noise(uv, {3, 200}, 2, salt + 2u)); }
  glm::dvec3 colour(glm::dvec2 uv) const {
    return glm::mix(earlywood, latewood, 0.7 * latewood_band(uv) + 0.3 * pores(uv));
  }
};

WoodGrain draw_wood_grain(matbase::UniformSource& random) {
  WoodGrain grain;
  grain.earlywood = pick_colour(random,
                                {from_srgb(0.80, 0.62, 0.44), from_srgb(0.70, 0.52, 0.36), from_srgb(0.86, 0.74, 0.58),
                                 from_srgb(0.58, 0.40, 0.32), from_srgb(0.66, 0.46, 0.34)},
                                0.08);
  grain.latewood = grain.earlywood * random.between(0.5, 0.65);
  grain.rings = 14 + static_cast<int>(random.choice(14));
  grain.salt = random.bits();
  return grain;
}

glm::dvec3 fabric_colour(matbase::UniformSource& random) {
  return pick_colour(random,
                     {from_srgb(0.60, 0.27, 0.27), from_srgb(0.27, 0.33, 0.55), from_srgb(0.65, 0.62, 0.55),
                      from_srgb(0.30, 0.45, 0.32), from_srgb(0.80, 0.70, 0.48), from_srgb(0.38, 0.38, 0.40)},
                     0.08);
}

// A woven cloth of `threads` threads per tile each way; `warp_on_top(i, j)` says which thread
// shows at crossing (i, j). Sheen from Principled's cloth lobe.
template <class WarpOnTop>
Recipe woven_fabric(matbase::UniformSource& random, int threads, WarpOnTop warp_on_top) {
  const glm::dvec3 colour = fabric_colour(random);
  const uint32_t salt = random.bits();
  const auto weave = [=](glm::dvec2 uv) {
    const double cu = uv.x * threads, cv = uv.y * threads;
    const int i = static_cast<int>(cu) % threads, j = static_cast<int>(cv) % threads;
    return warp_on_top(i, j) ? thread_profile(fract(cu)) : thread_profile(fract(cv));
  };
  Recipe recipe;
  recipe.texel = [=](glm::dvec2 uv) {
    const double h = weave(uv);
    const double slub = fractal_noise(uv, {4, 4}, 3, salt);
    Texel t;
    t.base_color = colour * (0.75 + 0.25 * h) * (0.92 + 0.16 * slub);
    t.roughness = 0.85 + 0.1 * (1.0 - h);
    t.height_m = 0.0003 * h;
    return t;
  };
  recipe.constants = {{P::Sheen, glm::dvec3(random.between(0.5, 1.0))}, {P::SheenTint, glm::dvec3(0.5)}};
  return recipe;
}

glm::dvec3 leather_colour(matbase::UniformSource& random) {
  return pick_colour(random,
                     {from_srgb(0.42, 0.28, 0.25), from_srgb(0.27, 0.25, 0.25), from_srgb(0.58, 0.38, 0.26),
                      from_srgb(0.50, 0.25, 0.25), from_srgb(0.32, 0.27, 0.25)},
                     0.06);
}

glm::dvec3 paper_colour(matbase::UniformSource& random) {
  return pick_colour(random,
                     {from_srgb(0.93, 0.92, 0.88), from_srgb(0.94, 0.94, 0.92), from_srgb(0.90, 0.86, 0.76),
                      from_srgb(0.84, 0.88, 0.92)},
                     0.02);
}

Recipe paper_with_fibres(const glm::dvec3& colour, double roughness, uint32_t salt) {
  Recipe recipe;
  recipe.texel = [=](glm::dvec2 uv) {
    const double fibres = fractal_noise(uv, {96, 96}, 3, salt);
    Texel t;
    t.base_color = colour * (0.96 + 0.04 * fibres);
    t.roughness = roughness + 0.05 * fibres;
    t.height_m = 0.00002 * fibres;
    return t;
  };
  return recipe;
}

}  // namespace

Recipe raw_wood(matbase::UniformSource& random) {
  const WoodGrain grain = draw_wood_grain(random);
  const double roughness = random.between(0.55, 0.7);
  Recipe recipe;
  recipe.texel = [=](glm::dvec2 uv) {
    const double band = grain.latewood_band(uv), pores = grain.pores(uv);
    Texel t;
    t.base_color = grain.colour(uv);
    t.roughness = roughness + 0.15 * band;
    t.height_m = -0.0005 * band - 0.0003 * pores;
    return t;
  };
  return recipe;
}

Recipe lacquered_wood(matbase::UniformSource& random) {
  const WoodGrain grain = draw_wood_grain(random);
  Recipe recipe;
  recipe.texel = [=](glm::dvec2 uv) {
    Texel t;
    t.base_color = grain.colour(uv);
    t.roughness = 0.4;
    t.height_m = -0.00005 * grain.pores(uv);  // the lacquer fills most of the pores
    return t;
  };
  recipe.constants = {{P::Clearcoat, glm::dvec3(random.between(0.7, 1.0))},
                      {P::ClearcoatRoughness, glm::dvec3(random.between(0.02, 0.08))}};
  return recipe;
}

Recipe painted_wood(matbase::UniformSource& random) {
  const glm::dvec3 paint = pick_colour(random,
                                       {from_srgb(0.90, 0.89, 0.85), from_srgb(0.27, 0.29, 0.32),
                                        from_srgb(0.45, 0.55, 0.50), from_srgb(0.70, 0.34, 0.27),
                                        from_srgb(0.55, 0.65, 0.75)},
                                       0.05);
  const WoodGrain grain = draw_wood_grain(random);
  const double roughness = random.between(0.35, 0.5);
  const uint32_t salt = random.bits();
  Recipe recipe;
  recipe.texel = [=](glm::dvec2 uv) {
    const double brush = fractal_noise(uv, {2, 40}, 3, salt);  // brush strokes along the grain
    Texel t;
    t.base_color = paint * (0.97 + 0.03 * brush);
    t.roughness = roughness + 0.05 * brush;
    t.height_m = -0.00008 * grain.latewood_band(uv) + 0.00002 * brush;  // the grain shows through
    return t;
  };
  return recipe;
}

Recipe wicker(matbase::UniformSource& random) {
  const glm::dvec3 colour = pick_colour(
      random, {from_srgb(0.78, 0.64, 0.42), from_srgb(0.62, 0.48, 0.34), from_srgb(0.82, 0.72, 0.52)}, 0.06);
  const uint32_t salt = random.bits();
  const int strands = 4 * (3 + static_cast<int>(random.choice(3)));  // blocks of two: a multiple of four wraps
  Recipe recipe;
  recipe.texel = [=](glm::dvec2 uv) {
    // Basket weave: blocks of two strands alternate between running along u and along v.
    const int block_u = static_cast<int>(uv.x * strands / 2.0), block_v = static_cast<int>(uv.y * strands / 2.0);
    const double across = (block_u + block_v) % 2 == 0 ? uv.y : uv.x;
    const double strand = thread_profile(fract(strands * across));
    Texel t;
    t.base_color = colour * (0.55 + 0.45 * strand) * (0.9 + 0.2 * fractal_noise(uv, {16, 16}, 3, salt));
    t.roughness = 0.6 + 0.25 * (1.0 - strand);
    t.height_m = 0.002 * strand;
    return t;
  };
  return recipe;
}

Recipe plain_weave_fabric(matbase::UniformSource& random) {
  const int threads = 2 * (16 + static_cast<int>(random.choice(9)));  // even: the checker wraps
  return woven_fabric(random, threads, [](int i, int j) { return (i + j) % 2 == 0; });
}

Recipe twill_fabric(matbase::UniformSource& random) {
  const int threads = 4 * (8 + static_cast<int>(random.choice(5)));  // a 2/2 twill repeats every four
  return woven_fabric(random, threads, [](int i, int j) { return ((i - j) % 4 + 4) % 4 < 2; });
}

Recipe velvet_fabric(matbase::UniformSource& random) {
  const glm::dvec3 colour = pick_colour(random,
                                        {from_srgb(0.50, 0.23, 0.27), from_srgb(0.23, 0.26, 0.45),
                                         from_srgb(0.24, 0.38, 0.28), from_srgb(0.45, 0.38, 0.24)},
                                        0.08);
  const uint32_t salt = random.bits();
  Recipe recipe;
  recipe.texel = [=](glm::dvec2 uv) {
    const double pile = fractal_noise(uv, {3, 3}, 4, salt);  // crushed pile
    Texel t;
    t.base_color = colour * (0.85 + 0.3 * pile);
    t.roughness = 0.95;
    t.height_m = 0.0001 * pile;
    return t;
  };
  recipe.constants = {{P::VelvetColor, glm::min(colour * 1.8, glm::dvec3(1.0))},
                      {P::VelvetSigma, glm::dvec3(random.between(0.3, 0.5))}};
  return recipe;
}

Recipe pebbled_leather(matbase::UniformSource& random) {
  const glm::dvec3 colour = leather_colour(random);
  const uint32_t salt = random.bits();
  const int pebbles = 40 + static_cast<int>(random.choice(20));
  Recipe recipe;
  recipe.texel = [=](glm::dvec2 uv) {
    const CellularSample cell = cellular_noise(uv, {pebbles, pebbles}, salt);
    const double crease = 1.0 - smoothstep(0.0, 0.12, cell.f2 - cell.f1);
    const double mottle = fractal_noise(uv, {4, 4}, 3, salt + 1u);
    Texel t;
    t.base_color = colour * (1.0 - 0.25 * crease) * (0.92 + 0.16 * mottle);
    t.roughness = 0.45 + 0.2 * crease + 0.05 * mottle;
    t.height_m = 0.0004 * smoothstep(0.0, 0.25, cell.f2 - cell.f1);
    return t;
  };
  return recipe;
}

Recipe smooth_leather(matbase::UniformSource& random) {
  const glm::dvec3 colour = leather_colour(random);
  const uint32_t salt = random.bits();
  const double roughness = random.between(0.3, 0.4);
  Recipe recipe;
  recipe.texel = [=](glm::dvec2 uv) {
    const double fine = fractal_noise(uv, {64, 64}, 3, salt);
    Texel t;
    t.base_color = colour * (0.9 + 0.2 * fractal_noise(uv, {3, 3}, 4, salt + 1u));
    t.roughness = roughness + 0.1 * fine;
    t.height_m = 0.00003 * fine;
    return t;
  };
  return recipe;
}

Recipe paper_sheet(matbase::UniformSource& random) {
  const glm::dvec3 colour = paper_colour(random);
  return paper_with_fibres(colour, random.between(0.85, 0.9), random.bits());
}

Recipe corrugated_cardboard(matbase::UniformSource& random) {
  const glm::dvec3 kraft = pick_colour(
      random, {from_srgb(0.68, 0.52, 0.36), from_srgb(0.74, 0.60, 0.44), from_srgb(0.60, 0.46, 0.32)}, 0.05);
  const uint32_t salt = random.bits();
  const int flutes = 24 + static_cast<int>(random.choice(12));
  Recipe recipe;
  recipe.texel = [=](glm::dvec2 uv) {
    // The flutes under the liner show as faint ridges along u.
    const double ridge = 0.5 + 0.5 * std::cos(2.0 * kPi * flutes * uv.y);
    const double fibres = fractal_noise(uv, {48, 48}, 3, salt);
    Texel t;
    t.base_color = kraft * (0.92 + 0.08 * ridge) * (0.95 + 0.1 * fibres);
    t.roughness = 0.85 + 0.05 * fibres;
    t.height_m = 0.0003 * ridge + 0.00002 * fibres;
    return t;
  };
  return recipe;
}

Recipe perforated_paper(matbase::UniformSource& random) {
  const glm::dvec3 colour = paper_colour(random);
  Recipe recipe = paper_with_fibres(colour, random.between(0.85, 0.9), random.bits());
  const int holes = 8 + static_cast<int>(random.choice(9));
  const double radius = random.between(0.2, 0.32);
  recipe.texel = [=, sheet = recipe.texel](glm::dvec2 uv) {
    Texel t = sheet(uv);
    t.opacity = perforation_opacity(uv, holes, radius, 0.04);
    return t;
  };
  return recipe;
}

}  // namespace matmaterial::library
