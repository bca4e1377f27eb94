#include "matgeom/uv/uv_distortion.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "uv/planar_triangle.h"

namespace matgeom {
namespace {

struct TriangleMap {
  double surface_area = 0.0;
  double uv_area = 0.0;  // signed
  double sigma_max = 0.0, sigma_min = 0.0;  // singular values of the surface-to-UV Jacobian
};

// The Jacobian J of the affine map from the triangle (in its own orthonormal frame) to its UV
// triangle, and J's singular values in closed form for a 2x2 matrix [[a, b], [c, d]]:
// sigma = sqrt(E^2 + H^2) +- sqrt(F^2 + G^2), E = (a + d)/2, F = (a - d)/2, G = (c + b)/2,
// H = (c - b)/2.
TriangleMap triangle_map(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2, const glm::dvec2& q0,
                         const glm::dvec2& q1, const glm::dvec2& q2) {
  TriangleMap m;
  const PlanarTriangle flat = planar_triangle(p0, p1, p2);
  if (!(flat.area > 0.0)) return m;
  m.surface_area = flat.area;
  const glm::dmat2 local(flat.corner[1], flat.corner[2]);
  const glm::dmat2 uv(q1 - q0, q2 - q0);
  const glm::dmat2 jacobian = uv * glm::inverse(local);
  m.uv_area = 0.5 * glm::determinant(uv);
  const double a = jacobian[0][0], c = jacobian[0][1], b = jacobian[1][0], d = jacobian[1][1];
  const double q = std::hypot(0.5 * (a + d), 0.5 * (c - b));
  const double r = std::hypot(0.5 * (a - d), 0.5 * (c + b));
  m.sigma_max = q + r;
  m.sigma_min = std::abs(q - r);
  return m;
}

}  // namespace

UvDistortion measure_uv_distortion(const std::vector<glm::dvec3>& positions,
                                   const std::vector<glm::uvec3>& triangles,
                                   const std::vector<glm::dvec2>& uvs) {
  if (uvs.size() != positions.size())
    throw std::invalid_argument("measure_uv_distortion: " + std::to_string(uvs.size()) + " UVs for " +
                                std::to_string(positions.size()) + " vertices");
  std::vector<TriangleMap> maps;
  maps.reserve(triangles.size());
  double positive_area = 0.0, negative_area = 0.0;
  for (size_t t = 0; t < triangles.size(); ++t) {
    const glm::uvec3 tri = triangles[t];
    if (tri.x >= positions.size() || tri.y >= positions.size() || tri.z >= positions.size())
      throw std::invalid_argument("measure_uv_distortion: triangle " + std::to_string(t) + " is out of range");
    maps.push_back(triangle_map(positions[tri.x], positions[tri.y], positions[tri.z], uvs[tri.x], uvs[tri.y],
                                uvs[tri.z]));
    (maps.back().uv_area >= 0.0 ? positive_area : negative_area) += std::abs(maps.back().uv_area);
  }
  const double orientation = positive_area >= negative_area ? 1.0 : -1.0;

  UvDistortion report;
  double surface_area = 0.0, uv_area = 0.0, angle_sum = 0.0, stretch_sum = 0.0, stretch_max = 0.0;
  for (const TriangleMap& m : maps) {
    if (!(m.surface_area > 0.0)) continue;
    if (!(m.sigma_min > 0.0) || m.uv_area == 0.0) {
      ++report.degenerate_triangles;
      continue;
    }
    if (m.uv_area * orientation < 0.0) ++report.flipped_triangles;
    const double angle = m.sigma_max / m.sigma_min - 1.0;
    surface_area += m.surface_area;
    angle_sum += m.surface_area * angle;
    report.angle_max = std::max(report.angle_max, angle);
    // The UV-to-surface map has singular values 1 / sigma_min >= 1 / sigma_max (Sander's
    // Gamma and gamma); L2 integrates (Gamma^2 + gamma^2) / 2 over the surface area (eq. 3).
    const double gamma_max = 1.0 / m.sigma_min, gamma_min = 1.0 / m.sigma_max;
    uv_area += std::abs(m.uv_area);
    stretch_sum += m.surface_area * 0.5 * (gamma_max * gamma_max + gamma_min * gamma_min);
    stretch_max = std::max(stretch_max, gamma_max);
  }
  if (surface_area > 0.0 && uv_area > 0.0) {
    report.angle_mean = angle_sum / surface_area;
    const double scale = std::sqrt(uv_area / surface_area);
    report.stretch_l2 = std::sqrt(stretch_sum / surface_area) * scale;
    report.stretch_linf = stretch_max * scale;
  }
  return report;
}

}  // namespace matgeom
