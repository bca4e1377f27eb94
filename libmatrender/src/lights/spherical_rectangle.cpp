#include "lights/spherical_rectangle.h"

#include <algorithm>
#include <cmath>

namespace matrender {

SphericalRectangle::SphericalRectangle(const glm::dvec3& origin, const glm::dvec3& corner,
                                       const glm::dvec3& ex, const glm::dvec3& ey)
    : origin_(origin) {
  const double ex_len = glm::length(ex);
  const double ey_len = glm::length(ey);
  x_ = ex / ex_len;
  y_ = ey / ey_len;
  z_ = glm::cross(x_, y_);
  const glm::dvec3 d = corner - origin;
  z0_ = glm::dot(d, z_);
  if (z0_ > 0.0) {  // keep the rectangle on the -z side of the local frame
    z_ = -z_;
    z0_ = -z0_;
  }
  x0_ = glm::dot(d, x_);
  y0_ = glm::dot(d, y_);
  x1_ = x0_ + ex_len;
  y1_ = y0_ + ey_len;

  // Normals of the four great-circle edges and the interior angles between them (eq. 4).
  const glm::dvec3 n0 = glm::normalize(glm::dvec3(0.0, z0_, -y0_));
  const glm::dvec3 n1 = glm::normalize(glm::dvec3(-z0_, 0.0, x1_));
  const glm::dvec3 n2 = glm::normalize(glm::dvec3(0.0, -z0_, y1_));
  const glm::dvec3 n3 = glm::normalize(glm::dvec3(z0_, 0.0, -x0_));
  const auto angle = [](const glm::dvec3& a, const glm::dvec3& b) {
    return std::acos(std::clamp(-glm::dot(a, b), -1.0, 1.0));
  };
  const double g0 = angle(n0, n1);
  const double g1 = angle(n1, n2);
  const double g2 = angle(n2, n3);
  const double g3 = angle(n3, n0);
  b0_ = n0.z;
  b1_ = n2.z;
  k_ = 2.0 * M_PI - g2 - g3;
  solid_angle_ = std::max(0.0, g0 + g1 - k_);
}

glm::dvec3 SphericalRectangle::sample(glm::dvec2 u) const {
  // x coordinate from the first variable (eqs. 7-9).
  const double au = u.x * solid_angle_ + k_;
  const double fu = (std::cos(au) * b0_ - b1_) / std::sin(au);
  double cu = std::copysign(1.0, fu) / std::sqrt(fu * fu + b0_ * b0_);
  cu = std::clamp(cu, -1.0, 1.0);
  double xu = -(cu * z0_) / std::sqrt(std::max(1e-300, 1.0 - cu * cu));
  xu = std::clamp(xu, x0_, x1_);
  // y coordinate from the second variable (eqs. 10-11).
  const double dist = std::sqrt(xu * xu + z0_ * z0_);
  const double h0 = y0_ / std::sqrt(dist * dist + y0_ * y0_);
  const double h1 = y1_ / std::sqrt(dist * dist + y1_ * y1_);
  const double hv = h0 + u.y * (h1 - h0);
  const double hv2 = hv * hv;
  const double yv = hv2 < 1.0 - 1e-12 ? hv * dist / std::sqrt(1.0 - hv2) : y1_;
  return origin_ + xu * x_ + std::clamp(yv, y0_, y1_) * y_ + z0_ * z_;
}

}  // namespace matrender
