#pragma once
// The cubic Hermite step every library blends with: procedural textures, the built-in vase's
// profile, the spot lamps' cone edge (the paper's rig and the renderer's, in double and float).
#include <algorithm>

namespace matbase {

// 3t^2 - 2t^3 of t clamped to [0, 1]: 0 below 0, 1 above 1, with zero slope at both ends.
template <typename Real>
inline Real smoothstep(Real t) {
  t = std::clamp(t, Real(0), Real(1));
  return t * t * (Real(3) - Real(2) * t);
}

// From 0 at `edge0` to 1 at `edge1` (GLSL's smoothstep).
template <typename Real>
inline Real smoothstep(Real edge0, Real edge1, Real x) {
  return smoothstep((x - edge0) / (edge1 - edge0));
}

}  // namespace matbase
