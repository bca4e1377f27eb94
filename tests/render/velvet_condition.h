#pragma once
// How far a float evaluation of the velvet lobe (libmatrender/src/bsdf/velvet_lobe.h) may stray
// from the double-precision reference, relative to its value, for tests that compare the two.
#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "bsdf/principled.h"

// ln D = -cot^2(theta_h) / s^2 - 4 ln sin(theta_h) + const, s the clamped sigma. Two float errors
// move it: (1) directions are unit vectors only to ~2^-22 rad, which turns h = normalize(wo + wi)
// by 2^-22 / |wo + wi|, and ln D changes at 2 cot / (sin^2 s^2) + 4 cot per radian of theta_h;
// (2) sin^2 = 1 - cos^2 computed in float carries 2^-24 / sin^2 relative, which cot^2 carries too
// and ln D (cot^2 / s^2 + 2) times. 0 without a velvet.
inline double velvet_condition(const matrender::PrincipledInputs& in, const glm::dvec3& wo, const glm::dvec3& wi) {
  if (in.color(matrender::MaterialParameter::VelvetColor) == glm::vec3(0.0f)) return 0.0;
  const double s = std::clamp(static_cast<double>(in.scalar(matrender::MaterialParameter::VelvetSigma)), 0.01, 1.0);
  const glm::dvec3 sum = wo + wi;
  const double length = glm::length(sum);
  if (!(length > 0.0)) return 0.0;
  const glm::dvec3 h = sum / length;
  const double sin2 = std::max(h.x * h.x + h.y * h.y, 1e-30);
  const double cot = h.z / std::sqrt(sin2);
  const double slope = 2.0 * cot / (sin2 * s * s) + 4.0 * cot;
  return 0x1p-22 * slope / length + 0x1p-24 / sin2 * (cot * cot / (s * s) + 2.0);
}
