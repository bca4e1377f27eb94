#pragma once
// atan2 for single-precision arguments from a truncated Taylor series evaluated in double
// precision: after reducing to |r| <= tan(pi/8), atan r = sum_k (-1)^k r^(2k+1) / (2k+1) loses
// less than r^21 / 21 < 1.2e-9 r when cut after ten terms, so the float result is within an
// ulp of the exact angle. glibc's atan2f costs several times the instructions.
#include <algorithm>
#include <cmath>

#include "matbase/pi.h"

namespace matrender {

// The angle of (x, y) in [-pi, pi]; 0 at the origin. Within one ulp of the exact value for
// finite arguments (tests/render/polynomial_atan2_test.cpp).
inline float polynomial_atan2(float y, float x) {
  constexpr double pi = matbase::kPi;
  constexpr double tan_pi_over_8 = 0.41421356237309504880;
  const double ax = std::abs(static_cast<double>(x)), ay = std::abs(static_cast<double>(y));
  const double big = std::max(ax, ay), small = std::min(ax, ay);
  if (!(big > 0.0)) return 0.0f;
  // atan(small / big) in [0, pi/4]; above tan(pi/8) use atan(q) = pi/4 + atan((q - 1) / (q + 1)).
  const bool upper = small > tan_pi_over_8 * big;
  const double r = upper ? (small - big) / (small + big) : small / big;
  // sum_k c_k w^k with c_k = 1 / (2k + 1), w = -r^2, by Estrin's scheme: pairs c_k + c_k+1 w
  // combined with w^2, w^4, w^8, a dependency chain of five multiply-adds instead of Horner's
  // nine (Knuth, TAOCP vol. 2, 4.6.4).
  const double w = -(r * r), w2 = w * w, w4 = w2 * w2, w8 = w4 * w4;
  const auto pair = [w](int k) { return 1.0 / (2 * k + 1) + (1.0 / (2 * k + 3)) * w; };
  const double series = (pair(0) + w2 * pair(2)) + w4 * (pair(4) + w2 * pair(6)) + w8 * pair(8);
  double angle = (upper ? 0.25 * pi : 0.0) + r * series;
  if (ay > ax) angle = 0.5 * pi - angle;
  if (x < 0.0f) angle = pi - angle;
  return static_cast<float>(std::copysign(angle, static_cast<double>(y)));
}

}  // namespace matrender
