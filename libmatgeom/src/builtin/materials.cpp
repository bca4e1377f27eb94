#include "builtin/materials.h"

#include <cmath>
#include <functional>
#include <vector>

#include "builtin/procedural_textures.h"
#include "matgeom/material_classes.h"

namespace matgeom::builtin {
namespace {

constexpr double kTwoPi = 6.28318530717958647692;
constexpr int kSize = kBuiltinTextureSize;

// Picks a palette entry and jitters it a little (sRGB-encoded colours).
glm::dvec3 pick(UniformSource& random, const std::vector<glm::dvec3>& palette, double jitter = 0.03) {
  const glm::dvec3 base = palette[random.choice(static_cast<uint32_t>(palette.size()))];
  return glm::clamp(base + glm::dvec3(random.between(-jitter, jitter)), 0.0, 1.0);
}

// Adds the three maps of a textured material: base colour (sRGB), packed metallic-roughness
// (glTF layout: G roughness, B metallic) and a normal map; factors stay 1 so the images rule.
MaterialDesc textured(ObjectAsset& asset, const std::string& slot, MaterialClass label,
                      const std::function<glm::dvec3(double, double)>& colour,
                      const std::function<glm::dvec2(double, double)>& roughness_metallic,
                      const std::function<double(double, double)>& height, double bump) {
  using P = MaterialParameter;
  MaterialDesc m(slot);
  m.label_id = label_id(label);
  m.set(P::BaseColor, 1.0).set(P::Metallic, 1.0).set(P::Roughness, 1.0);
  m.set_image(P::BaseColor, static_cast<int>(asset.images.size()));
  asset.images.push_back(rgb_image(slot + "#base_color", kSize, colour));
  m.set_metallic_roughness_image(static_cast<int>(asset.images.size()));
  asset.images.push_back(rgb_image(slot + "#metallic_roughness", kSize, [&](double u, double v) {
    const glm::dvec2 rm = roughness_metallic(u, v);
    return glm::dvec3(1.0, rm.x, rm.y);
  }));
  m.normal_image = static_cast<int>(asset.images.size());
  asset.images.push_back(normal_map_image(slot + "#normal", kSize, height, bump));
  return m;
}

MaterialDesc constant(const std::string& slot, MaterialClass label, const glm::dvec3& srgb, double roughness,
                      double metallic) {
  MaterialDesc m(slot);
  m.label_id = label_id(label);
  m.set(MaterialParameter::BaseColor, srgb_to_linear(srgb));
  m.set(MaterialParameter::Roughness, roughness).set(MaterialParameter::Metallic, metallic);
  return m;
}

MaterialDesc wood(ObjectAsset& asset, const std::string& slot, UniformSource& random) {
  const glm::dvec3 light =
      pick(random, {{0.78, 0.60, 0.42}, {0.66, 0.45, 0.28}, {0.86, 0.74, 0.56}, {0.52, 0.33, 0.20}});
  const glm::dvec3 dark = light * random.between(0.55, 0.7);
  const uint32_t salt = random.bits();
  const int rings = 24 + static_cast<int>(random.choice(16));  // whole periods: tileable
  const double gloss = random.between(0.3, 0.5);
  // Growth rings across v, warped by noise; pores as fine streaks along u.
  const auto grain = [=](double u, double v) {
    const double warp = 0.6 * fractal_noise(u, v, 2, salt);
    return 0.5 + 0.5 * std::sin(kTwoPi * (rings * v + warp));
  };
  return textured(
      asset, slot, MaterialClass::Wood,
      [=](double u, double v) {
        const double pores = fractal_noise(u, v, 4, 64, salt + 5u);  // streaks along the grain
        return glm::mix(light, dark, 0.75 * grain(u, v) + 0.25 * pores);
      },
      [=](double u, double v) { return glm::dvec2(gloss + 0.15 * grain(u, v), 0.0); }, grain, 1.5);
}

MaterialDesc fabric(ObjectAsset& asset, const std::string& slot, UniformSource& random) {
  const glm::dvec3 colour = pick(random, {{0.55, 0.16, 0.14},
                                          {0.20, 0.30, 0.52},
                                          {0.62, 0.60, 0.52},
                                          {0.30, 0.44, 0.30},
                                          {0.80, 0.70, 0.45},
                                          {0.36, 0.36, 0.38}});
  const uint32_t salt = random.bits();
  const int threads = 96 + 32 * static_cast<int>(random.choice(3));
  // A plain weave: warp threads along v rise where weft threads along u sink, alternating.
  const auto weave = [=](double u, double v) {
    const double a = std::sin(kTwoPi * threads * u), b = std::sin(kTwoPi * threads * v);
    return 0.5 + 0.25 * (a * std::abs(std::sin(kTwoPi * threads * 0.5 * v)) +
                         b * std::abs(std::sin(kTwoPi * threads * 0.5 * u)));
  };
  return textured(
      asset, slot, MaterialClass::Fabric,
      [=](double u, double v) {
        const double slub = fractal_noise(u, v, 8, salt);
        return colour * (0.75 + 0.25 * weave(u, v)) * (0.9 + 0.2 * slub);
      },
      [=](double u, double v) { return glm::dvec2(0.82 + 0.12 * (1.0 - weave(u, v)), 0.0); }, weave, 2.0);
}

MaterialDesc leather(ObjectAsset& asset, const std::string& slot, UniformSource& random) {
  const glm::dvec3 colour =
      pick(random, {{0.36, 0.20, 0.12}, {0.12, 0.10, 0.09}, {0.55, 0.34, 0.18}, {0.45, 0.12, 0.10}});
  const uint32_t salt = random.bits();
  const auto pebbles = [=](double u, double v) { return fractal_noise(u, v, 48, salt); };
  return textured(
      asset, slot, MaterialClass::Leather,
      [=](double u, double v) {
        return colour * (0.8 + 0.35 * pebbles(u, v)) * (0.9 + 0.2 * fractal_noise(u, v, 4, salt + 1u));
      },
      [=](double u, double v) { return glm::dvec2(0.45 + 0.25 * pebbles(u, v), 0.0); }, pebbles, 3.0);
}

MaterialDesc brushed_metal(ObjectAsset& asset, const std::string& slot, UniformSource& random) {
  const glm::dvec3 colour =
      pick(random, {{0.78, 0.78, 0.80}, {0.91, 0.78, 0.50}, {0.80, 0.55, 0.45}, {0.55, 0.56, 0.58}}, 0.02);
  const uint32_t salt = random.bits();
  // Streaks along u: 2 noise cells along u, 64 across v.
  const auto streaks = [=](double u, double v) { return fractal_noise(u, v, 2, 64, salt); };
  const double base_roughness = random.between(0.18, 0.32);
  return textured(
      asset, slot, MaterialClass::Metal, [=](double u, double v) { return colour * (0.92 + 0.08 * streaks(u, v)); },
      [=](double u, double v) { return glm::dvec2(base_roughness + 0.12 * streaks(u, v), 1.0); }, streaks, 0.5);
}

MaterialDesc ceramic(ObjectAsset& asset, const std::string& slot, UniformSource& random) {
  const glm::dvec3 light =
      pick(random, {{0.93, 0.91, 0.86}, {0.78, 0.85, 0.76}, {0.60, 0.72, 0.85}, {0.85, 0.55, 0.40}});
  const glm::dvec3 dark = light * 0.8;
  const uint32_t salt = random.bits();
  const auto mottling = [=](double u, double v) { return fractal_noise(u, v, 6, salt); };
  return textured(
      asset, slot, MaterialClass::Ceramic, [=](double u, double v) { return glm::mix(light, dark, mottling(u, v)); },
      [=](double u, double v) { return glm::dvec2(0.12 + 0.15 * mottling(u, v), 0.0); },
      [=](double u, double v) { return fractal_noise(u, v, 24, salt + 2u); }, 0.8);
}

MaterialDesc concrete(ObjectAsset& asset, const std::string& slot, UniformSource& random) {
  const glm::dvec3 grey = pick(random, {{0.62, 0.61, 0.58}, {0.50, 0.50, 0.50}, {0.70, 0.66, 0.60}});
  const uint32_t salt = random.bits();
  const auto speckle = [=](double u, double v) { return fractal_noise(u, v, 64, salt); };
  return textured(
      asset, slot, MaterialClass::Concrete,
      [=](double u, double v) {
        return grey * (0.8 + 0.3 * speckle(u, v)) * (0.9 + 0.15 * fractal_noise(u, v, 4, salt + 1u));
      },
      [=](double u, double v) { return glm::dvec2(0.85 + 0.1 * speckle(u, v), 0.0); }, speckle, 2.5);
}

MaterialDesc paper(ObjectAsset& asset, const std::string& slot, UniformSource& random) {
  const glm::dvec3 colour = pick(random, {{0.93, 0.91, 0.84}, {0.96, 0.95, 0.92}, {0.90, 0.85, 0.74}}, 0.02);
  const uint32_t salt = random.bits();
  const auto fibres = [=](double u, double v) { return fractal_noise(u, v, 96, salt); };
  return textured(
      asset, slot, MaterialClass::Paper, [=](double u, double v) { return colour * (0.94 + 0.06 * fibres(u, v)); },
      [=](double u, double v) { return glm::dvec2(0.88 + 0.08 * fibres(u, v), 0.0); }, fibres, 0.6);
}

MaterialDesc wicker(ObjectAsset& asset, const std::string& slot, UniformSource& random) {
  const glm::dvec3 colour = pick(random, {{0.76, 0.62, 0.40}, {0.60, 0.45, 0.28}, {0.82, 0.72, 0.52}});
  const uint32_t salt = random.bits();
  const int strands = 40;
  // Basket weave: alternating blocks of strands along u and along v.
  const auto strand = [=](double u, double v) {
    const bool along_u = (static_cast<int>(u * strands / 2.0) + static_cast<int>(v * strands / 2.0)) % 2 == 0;
    const double across = along_u ? v : u;
    return std::pow(std::abs(std::sin(kTwoPi * strands * across)), 0.5);
  };
  return textured(
      asset, slot, MaterialClass::Wood,
      [=](double u, double v) {
        return colour * (0.55 + 0.45 * strand(u, v)) * (0.9 + 0.2 * fractal_noise(u, v, 16, salt));
      },
      [=](double u, double v) { return glm::dvec2(0.6 + 0.25 * (1.0 - strand(u, v)), 0.0); }, strand, 2.0);
}

}  // namespace

MaterialDesc make_material(ObjectAsset& asset, const std::string& slot, Finish finish, UniformSource& random) {
  switch (finish) {
    case Finish::Wood:
      return wood(asset, slot, random);
    case Finish::PaintedWood:
      return constant(slot, MaterialClass::Wood,
                      pick(random, {{0.90, 0.89, 0.85}, {0.20, 0.22, 0.25}, {0.45, 0.55, 0.50}, {0.70, 0.30, 0.22}}),
                      random.between(0.35, 0.55), 0.0);
    case Finish::Fabric:
      return fabric(asset, slot, random);
    case Finish::Leather:
      return leather(asset, slot, random);
    case Finish::BrushedMetal:
      return brushed_metal(asset, slot, random);
    case Finish::Plastic:
      return constant(slot, MaterialClass::Plastic,
                      pick(random, {{0.85, 0.20, 0.15},
                                    {0.15, 0.45, 0.75},
                                    {0.95, 0.95, 0.93},
                                    {0.20, 0.65, 0.35},
                                    {0.12, 0.12, 0.13},
                                    {0.95, 0.75, 0.20}}),
                      random.between(0.25, 0.5), 0.0);
    case Finish::Ceramic:
      return ceramic(asset, slot, random);
    case Finish::Concrete:
      return concrete(asset, slot, random);
    case Finish::Paper:
      return paper(asset, slot, random);
    case Finish::Wicker:
      return wicker(asset, slot, random);
  }
  return constant(slot, MaterialClass::Background, glm::dvec3(0.8), 0.5, 0.0);
}

}  // namespace matgeom::builtin
