#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <random>

#include "matbase/pi.h"
#include "util/polynomial_atan2.h"

using matrender::polynomial_atan2;

TEST_CASE("polynomial_atan2 is within an ulp of double-precision atan2", "[render]") {
  std::mt19937_64 rng(20261123);
  std::uniform_real_distribution<double> exponent(-20.0, 20.0), sign(-1.0, 1.0);
  double worst = 0.0;  // in ulps
  for (int i = 0; i < 1000000; ++i) {
    const float y = static_cast<float>(std::copysign(std::exp2(exponent(rng)), sign(rng)));
    const float x = static_cast<float>(std::copysign(std::exp2(exponent(rng)), sign(rng)));
    const double exact = std::atan2(static_cast<double>(y), static_cast<double>(x));
    // One ulp of the float nearest the exact angle.
    const float nearest = static_cast<float>(exact);
    const double ulp = std::nextafter(std::abs(nearest), INFINITY) - std::abs(nearest);
    worst = std::max(worst, std::abs(polynomial_atan2(y, x) - exact) / ulp);
  }
  CHECK(worst <= 1.0);
}

TEST_CASE("polynomial_atan2 on the axes, the diagonals and the origin", "[render]") {
  constexpr float kPi = matbase::kPiAs<float>;
  CHECK(polynomial_atan2(0.0f, 1.0f) == 0.0f);
  CHECK(polynomial_atan2(0.0f, 0.0f) == 0.0f);
  CHECK(polynomial_atan2(1.0f, 0.0f) == Approx(0.5f * kPi).epsilon(1e-7));
  CHECK(polynomial_atan2(-1.0f, 0.0f) == Approx(-0.5f * kPi).epsilon(1e-7));
  CHECK(polynomial_atan2(0.0f, -1.0f) == Approx(kPi).epsilon(1e-7));
  CHECK(polynomial_atan2(1.0f, 1.0f) == Approx(0.25f * kPi).epsilon(1e-7));
  CHECK(polynomial_atan2(-2.0f, -2.0f) == Approx(-0.75f * kPi).epsilon(1e-7));
  CHECK(polynomial_atan2(1e-30f, 1e30f) == Approx(1e-60).margin(1e-45));
}
