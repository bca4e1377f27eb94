#include "lights/spherical_rectangle.h"

#include <algorithm>
#include <cmath>

#include "sampling/warp.h"
#include "util/polynomial_atan2.h"

namespace matrender {

SphericalRectangle::SphericalRectangle(const glm::vec3& origin, const Rectangle3& rect)
    : origin_(origin), x_(rect.x), y_(rect.y), z_(rect.z) {
  const glm::vec3 d = rect.corner - origin;
  z0_ = glm::dot(d, z_);
  if (z0_ > 0.0f) {  // keep the rectangle on the -z side of the local frame
    z_ = -z_;
    z0_ = -z0_;
  }
  x0_ = glm::dot(d, x_);
  y0_ = glm::dot(d, y_);
  x1_ = x0_ + rect.length_x;
  y1_ = y0_ + rect.length_y;

  // Interior angles g_i = acos(-n_i . n_i+1) of the spherical quadrilateral, from the unit
  // normals n_i of its great-circle edges (eq. 4). Written as g_i = pi/2 + s_i with
  // s_i = atan(x y / (|z0| r)) for the corner (x, y) the two edges share (r its distance), the
  // solid angle g0 + g1 + g2 + g3 - 2 pi = s0 + s1 + s2 + s3 has no 2 pi to cancel and every
  // term is well conditioned, unlike acos or asin of n_i . n_i+1 near +-1 at grazing views.
  // Each s_i is the argument of the complex number (|z0| r, +-x y); a pair of them (a sum in
  // [-pi, pi]) is the argument of their product, so two atan2 give the four angles' sums.
  const float z0_sq = z0_ * z0_;
  const float h = -z0_;
  struct Complex {
    float re, im;
  };
  const auto corner = [&](float x, float y, float sign) {
    return Complex{h * std::sqrt(x * x + y * y + z0_sq), sign * x * y};
  };
  const auto argument_of_product = [](Complex a, Complex b) {
    return polynomial_atan2(a.re * b.im + a.im * b.re, a.re * b.re - a.im * b.im);
  };
  const float s0_plus_s1 = argument_of_product(corner(x1_, y0_, -1.0f), corner(x1_, y1_, 1.0f));
  const float s2_plus_s3 = argument_of_product(corner(x0_, y1_, -1.0f), corner(x0_, y0_, 1.0f));
  // z components of n0 and n2, the constants b0, b1 of the sampling equations.
  const float z0_y0_sq = z0_sq + y0_ * y0_;
  b0_ = -y0_ / std::sqrt(z0_y0_sq);
  one_minus_b0_sq_ = z0_sq / z0_y0_sq;
  b1_ = y1_ / std::sqrt(z0_sq + y1_ * y1_);
  k_ = kPi - s2_plus_s3;  // 2 pi - g2 - g3
  solid_angle_ = std::max(0.0f, s0_plus_s1 + s2_plus_s3);
}

glm::vec3 SphericalRectangle::sample(glm::vec2 u) const {
  // x coordinate from the first variable (eqs. 7-9): fu = n / s with n = cos(au) b0 - b1,
  // s = sin(au); cu = sign(fu) / sqrt(fu^2 + b0^2); xu = -cu z0 / sqrt(1 - cu^2). Since
  // 1 - cu^2 = (fu^2 + b0^2 - 1) cu^2 and 1 - b0^2 = z0^2 / (z0^2 + y0^2), the last two fold into
  // xu = -sign(n) z0 s / sqrt(n^2 - (1 - b0^2) s^2): one square root and one division on the
  // dependency chain instead of two and three (the sampling cost is mostly that chain).
  const float au = u.x * solid_angle_ + k_;
  const float s = std::sin(au);
  const float n = std::cos(au) * b0_ - b1_;
  const float radicand = std::max(n * n - one_minus_b0_sq_ * s * s, 1e-30f);
  const float xu = std::clamp(-z0_ * std::copysign(1.0f, n) * s / std::sqrt(radicand), x0_, x1_);
  // y coordinate from the second variable (eqs. 10-11), with d2 = xu^2 + z0^2 the squared
  // distance from the origin to the line x = xu of the rectangle's plane.
  const float d2 = xu * xu + z0_ * z0_;
  const float h0 = y0_ / std::sqrt(d2 + y0_ * y0_);
  const float h1 = y1_ / std::sqrt(d2 + y1_ * y1_);
  const float hv = h0 + u.y * (h1 - h0);
  const float hv2 = hv * hv;
  // Where |hv| reaches 1 in float the point lies at the far edge on hv's side.
  const float yv = hv2 < 1.0f - 1e-6f ? hv * std::sqrt(d2 / (1.0f - hv2)) : (hv > 0.0f ? y1_ : y0_);
  return origin_ + xu * x_ + std::clamp(yv, y0_, y1_) * y_ + z0_ * z_;
}

}  // namespace matrender
