#pragma once
// What kind of scattering a lobe does, in pbrt-v4's terms (section 9.1.2, BxDFFlags): which side
// of the surface the light leaves to (reflection or transmission) and how it spreads (diffuse,
// glossy, or specular = a delta distribution no light sample can hit), and Cycles' "transparent"
// (light passing straight through a surface's missing coverage, not scattered by it). The
// integrator, the light sampler and the bounce counters decide from these flags alone.
#include <cstdint>

namespace matrender {

enum class BxDFFlags : uint32_t {
  None = 0,
  Reflection = 1u << 0,
  Transmission = 1u << 1,
  Diffuse = 1u << 2,
  Glossy = 1u << 3,
  Specular = 1u << 4,
  Transparent = 1u << 5,
  DiffuseReflection = Diffuse | Reflection,
  GlossyReflection = Glossy | Reflection,
  SpecularReflection = Specular | Reflection,
  DiffuseTransmission = Diffuse | Transmission,
  GlossyTransmission = Glossy | Transmission,
  SpecularTransmission = Specular | Transmission,
  // Straight through: a delta transmission that is no bounce.
  TransparentTransmission = Transparent | Specular | Transmission,
};

constexpr BxDFFlags operator|(BxDFFlags a, BxDFFlags b) {
  return static_cast<BxDFFlags>(static_cast<uint32_t>(a) | static_cast<uint32_t>(b));
}
constexpr BxDFFlags operator&(BxDFFlags a, BxDFFlags b) {
  return static_cast<BxDFFlags>(static_cast<uint32_t>(a) & static_cast<uint32_t>(b));
}
constexpr BxDFFlags& operator|=(BxDFFlags& a, BxDFFlags b) { return a = a | b; }

constexpr bool any(BxDFFlags f) { return f != BxDFFlags::None; }
constexpr bool is_reflective(BxDFFlags f) { return any(f & BxDFFlags::Reflection); }
constexpr bool is_transmissive(BxDFFlags f) { return any(f & BxDFFlags::Transmission); }
constexpr bool is_diffuse(BxDFFlags f) { return any(f & BxDFFlags::Diffuse); }
constexpr bool is_glossy(BxDFFlags f) { return any(f & BxDFFlags::Glossy); }
constexpr bool is_specular(BxDFFlags f) { return any(f & BxDFFlags::Specular); }
constexpr bool is_transparent(BxDFFlags f) { return any(f & BxDFFlags::Transparent); }
// Some lobe a light sample can reach (NEE contributes).
constexpr bool is_non_specular(BxDFFlags f) { return any(f & (BxDFFlags::Diffuse | BxDFFlags::Glossy)); }

}  // namespace matrender
