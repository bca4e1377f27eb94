// Plastic, rubber, metal and glass. Metals take their base colour from measured reflectances
// (matmaterial/metal_reflectances.h); reflectances stay within their class's range
// (material_library.cpp); relief is in metres, at the tile's physical size
// (the style table's).
#include <cmath>

#include "matmaterial/library/periodic_noise.h"
#include "library/style_kit.h"
#include "library/styles.h"
#include "matmaterial/metal_reflectances.h"

namespace matmaterial::library {
namespace {

using P = MaterialParameter;

glm::dvec3 plastic_colour(matbase::UniformSource& random) {
  return pick_colour(random,
                     {from_srgb(0.80, 0.20, 0.20), from_srgb(0.20, 0.40, 0.72), from_srgb(0.90, 0.90, 0.88),
                      from_srgb(0.20, 0.55, 0.30), from_srgb(0.22, 0.22, 0.22), from_srgb(0.92, 0.75, 0.20),
                      from_srgb(0.90, 0.55, 0.20)},
                     0.04);
}

glm::dvec3 rubber_colour(matbase::UniformSource& random) {
  return pick_colour(random,
                     {from_srgb(0.21, 0.21, 0.22), from_srgb(0.24, 0.23, 0.22), from_srgb(0.22, 0.24, 0.28),
                      from_srgb(0.30, 0.23, 0.21)},
                     0.04);
}

glm::dvec3 metal_reflectance(matbase::UniformSource& random) {
  return kMetalReflectances[random.choice(static_cast<uint32_t>(kMetalReflectances.size()))].f0;
}

Recipe metal(std::function<Texel(glm::dvec2)> texel) {
  Recipe recipe;
  recipe.texel = [texel = std::move(texel)](glm::dvec2 uv) {
    Texel t = texel(uv);
    t.metallic = 1.0;
    return t;
  };
  return recipe;
}

Recipe glass(const glm::dvec3& tint, double ior) {
  Recipe recipe;
  recipe.texel = [=](glm::dvec2) {
    Texel t;
    t.base_color = tint;
    t.roughness = 0.0;
    return t;
  };
  recipe.constants = {{P::Transmission, glm::dvec3(1.0)}, {P::Ior, glm::dvec3(ior)}};
  return recipe;
}

}  // namespace

Recipe glossy_plastic(matbase::UniformSource& random) {
  const glm::dvec3 colour = plastic_colour(random);
  const double roughness = random.between(0.05, 0.2);
  Recipe recipe;
  recipe.texel = [=](glm::dvec2) {
    Texel t;
    t.base_color = colour;
    t.roughness = roughness;
    return t;  // moulded smooth: every parameter a constant
  };
  return recipe;
}

Recipe matte_plastic(matbase::UniformSource& random) {
  const glm::dvec3 colour = plastic_colour(random);
  const double roughness = random.between(0.45, 0.65);
  const uint32_t salt = random.bits();
  Recipe recipe;
  recipe.texel = [=](glm::dvec2 uv) {
    const double fine = fractal_noise(uv, {96, 96}, 3, salt);
    Texel t;
    t.base_color = colour;
    t.roughness = roughness + 0.05 * fine;
    t.height_m = 0.00001 * fine;
    return t;
  };
  return recipe;
}

Recipe textured_plastic(matbase::UniformSource& random) {
  const glm::dvec3 colour = plastic_colour(random);
  const double roughness = random.between(0.4, 0.5);
  const uint32_t salt = random.bits();
  Recipe recipe;
  recipe.texel = [=](glm::dvec2 uv) {
    const double bump = smoothstep(0.0, 0.5, cellular_noise(uv, {160, 160}, salt).f1);  // a moulded stipple
    Texel t;
    t.base_color = colour;
    t.roughness = roughness + 0.1 * bump;
    t.height_m = 0.00004 * (1.0 - bump);
    return t;
  };
  return recipe;
}

Recipe matte_rubber(matbase::UniformSource& random) {
  const glm::dvec3 colour = rubber_colour(random);
  const double roughness = random.between(0.75, 0.9);
  const uint32_t salt = random.bits();
  Recipe recipe;
  recipe.texel = [=](glm::dvec2 uv) {
    const double fine = fractal_noise(uv, {128, 128}, 3, salt);
    Texel t;
    t.base_color = colour * (0.95 + 0.1 * fine);
    t.roughness = roughness + 0.05 * fine;
    t.height_m = 0.00002 * fine;
    return t;
  };
  return recipe;
}

Recipe ribbed_rubber(matbase::UniformSource& random) {
  Recipe recipe = matte_rubber(random);
  const int ribs = 20 + static_cast<int>(random.choice(11));
  recipe.texel = [=, surface = recipe.texel](glm::dvec2 uv) {
    Texel t = surface(uv);
    t.height_m += 0.001 * thread_profile(fract(ribs * uv.y));
    return t;
  };
  return recipe;
}

Recipe brushed_metal(matbase::UniformSource& random) {
  const glm::dvec3 f0 = metal_reflectance(random);
  const double roughness = random.between(0.2, 0.3);
  const uint32_t salt = random.bits();
  return metal([=](glm::dvec2 uv) {
    const double streaks = fractal_noise(uv, {1, 256}, 3, salt);  // brushed along u
    Texel t;
    t.base_color = f0 * (0.96 + 0.04 * streaks);
    t.roughness = roughness + 0.1 * streaks;
    t.height_m = 0.00002 * streaks;
    return t;
  });
}

Recipe polished_metal(matbase::UniformSource& random) {
  const glm::dvec3 f0 = metal_reflectance(random);
  const double roughness = random.between(0.04, 0.1);
  const uint32_t salt = random.bits();
  return metal([=](glm::dvec2 uv) {
    Texel t;
    t.base_color = f0;
    t.roughness = roughness + 0.04 * fractal_noise(uv, {3, 3}, 4, salt);  // smudges
    return t;
  });
}

Recipe hammered_metal(matbase::UniformSource& random) {
  const glm::dvec3 f0 = metal_reflectance(random);
  const double roughness = random.between(0.15, 0.3);
  const int dimples = 16 + static_cast<int>(random.choice(10));
  const uint32_t salt = random.bits();
  return metal([=](glm::dvec2 uv) {
    const double f1 = cellular_noise(uv, {dimples, dimples}, salt).f1;
    Texel t;
    t.base_color = f0;
    t.roughness = roughness + 0.05 * smoothstep(0.2, 0.7, f1);
    t.height_m = -0.001 * std::max(0.0, 1.0 - (f1 / 0.7) * (f1 / 0.7));
    return t;
  });
}

Recipe perforated_metal(matbase::UniformSource& random) {
  const glm::dvec3 f0 = metal_reflectance(random);
  const double roughness = random.between(0.3, 0.45);
  const int holes = 20 + static_cast<int>(random.choice(13));
  const double radius = random.between(0.25, 0.35);
  const uint32_t salt = random.bits();
  return metal([=](glm::dvec2 uv) {
    const double grain = fractal_noise(uv, {64, 64}, 2, salt);
    Texel t;
    t.base_color = f0 * (0.97 + 0.03 * grain);
    t.roughness = roughness + 0.05 * grain;
    t.opacity = perforation_opacity(uv, holes, radius, 0.04);
    return t;
  });
}

Recipe clear_glass(matbase::UniformSource& random) {
  return glass(glm::dvec3(random.between(0.96, 1.0)), random.between(1.47, 1.52));
}

Recipe tinted_glass(matbase::UniformSource& random) {
  const glm::dvec3 tint = pick_colour(random, {{0.70, 0.85, 0.70}, {0.85, 0.70, 0.50}, {0.65, 0.78, 0.92}, {0.78, 0.78, 0.78}}, 0.03);
  return glass(tint, random.between(1.47, 1.52));
}

Recipe frosted_glass(matbase::UniformSource& random) {
  const glm::dvec3 tint(random.between(0.94, 1.0));
  Recipe recipe = glass(tint, random.between(1.47, 1.52));
  const double roughness = random.between(0.25, 0.35);
  const uint32_t salt = random.bits();
  recipe.texel = [=](glm::dvec2 uv) {  // acid-etched: rough, unevenly
    Texel t;
    t.base_color = tint;
    t.roughness = roughness + 0.08 * fractal_noise(uv, {8, 8}, 4, salt);
    return t;
  };
  return recipe;
}

}  // namespace matmaterial::library
