#pragma once
// The colour of a blackbody at a temperature, as Blender 3.4's Blackbody node gives it: the
// light's linear Rec.709 RGB scaled to a luminance of 1, negative channels (outside Rec.709's
// gamut, below about 1900 K) set to 0. docs/conventions.md, "Lamps", says where it agrees with
// Cycles'.
#include <glm/glm.hpp>

namespace matrender {

// The temperatures the Blackbody node distinguishes: Cycles 3.4 returns one colour below 800 K
// and another from 12,000 K up, so a temperature outside is refused rather than silently clamped.
constexpr double kMinBlackbodyKelvin = 800.0;
constexpr double kMaxBlackbodyKelvin = 12000.0;

// For kelvin in [kMinBlackbodyKelvin, kMaxBlackbodyKelvin].
glm::dvec3 blackbody_color(double kelvin);

}  // namespace matrender
