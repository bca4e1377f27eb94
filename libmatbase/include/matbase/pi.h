#pragma once
// pi, stated once for every library: as a double for geometry, materials and references, and
// rounded to the float the renderer computes in (the same value as the float literal).

namespace matbase {

template <typename Real>
constexpr Real kPiAs = static_cast<Real>(3.14159265358979323846);

constexpr double kPi = kPiAs<double>;

static_assert(kPiAs<float> == 3.14159265358979323846f, "pi as a float is the float nearest to pi");

}  // namespace matbase
