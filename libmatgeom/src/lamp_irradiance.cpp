#include "matgeom/lamp_irradiance.h"

#include <algorithm>
#include <cmath>

#include "matbase/smoothstep.h"

namespace matgeom {

double quad_projected_solid_angle(const std::array<glm::dvec3, 4>& corners, const glm::dvec3& normal) {
  // Sutherland-Hodgman against the plane n.v = 0: a quad keeps at most five vertices.
  std::array<glm::dvec3, 5> clipped;
  size_t count = 0;
  for (size_t k = 0; k < corners.size(); ++k) {
    const glm::dvec3& current = corners[k];
    const glm::dvec3& next = corners[(k + 1) % corners.size()];
    const double height_current = glm::dot(normal, current);
    const double height_next = glm::dot(normal, next);
    if (height_current >= 0.0) clipped[count++] = current;
    if ((height_current >= 0.0) != (height_next >= 0.0)) {
      const double t = height_current / (height_current - height_next);
      clipped[count++] = current + t * (next - current);
    }
  }
  double sum = 0.0;
  for (size_t k = 0; k < count; ++k) {
    const glm::dvec3& a = clipped[k];
    const glm::dvec3& b = clipped[(k + 1) % count];
    const glm::dvec3 a_cross_b = glm::cross(a, b);
    const double sine_part = glm::length(a_cross_b);
    if (!(sine_part > 0.0)) continue;  // coincident directions subtend no angle
    const double angle = std::atan2(sine_part, glm::dot(a, b));
    sum += angle * glm::dot(normal, a_cross_b) / sine_part;
  }
  // The sign follows the winding as seen from the point; the irradiance is its magnitude.
  return 0.5 * std::abs(sum);
}

double rect_lamp_irradiance(const glm::dmat4& light_to_world, double size_x, double size_y, double radiance,
                            const glm::dvec3& point, const glm::dvec3& normal) {
  const glm::dvec3 axis_x(light_to_world[0]);
  const glm::dvec3 axis_y(light_to_world[1]);
  const glm::dvec3 backward(light_to_world[2]);
  const glm::dvec3 to_lamp = glm::dvec3(light_to_world[3]) - point;
  // Only points on the emitting (-Z) side see the lamp's front.
  if (!(glm::dot(to_lamp, backward) > 0.0)) return 0.0;
  const glm::dvec3 half_x = 0.5 * size_x * axis_x;
  const glm::dvec3 half_y = 0.5 * size_y * axis_y;
  const std::array<glm::dvec3, 4> corners{to_lamp - half_x - half_y, to_lamp + half_x - half_y,
                                          to_lamp + half_x + half_y, to_lamp - half_x + half_y};
  return radiance * quad_projected_solid_angle(corners, normal);
}

double spot_lamp_irradiance(const glm::dvec3& position, const glm::dvec3& forward, double spot_angle, double blend,
                            double intensity, const glm::dvec3& point, const glm::dvec3& normal) {
  const glm::dvec3 to_point = point - position;
  const double distance_squared = glm::dot(to_point, to_point);
  // A delta lamp gives no defined irradiance at its own position.
  if (!(distance_squared > 0.0)) return 0.0;
  const double distance = std::sqrt(distance_squared);
  const double cos_surface = std::min(1.0, -glm::dot(normal, to_point) / distance);
  if (!(cos_surface > 0.0)) return 0.0;
  const double cos_axis = glm::dot(forward, to_point) / distance;
  const double cos_half = std::cos(0.5 * spot_angle);
  if (!(cos_axis > cos_half)) return 0.0;
  double falloff = cos_axis;
  const double smooth_width = (1.0 - cos_half) * blend;
  const double into_cone = cos_axis - cos_half;
  if (into_cone < smooth_width) falloff *= matbase::smoothstep(into_cone / smooth_width);
  return intensity * falloff * cos_surface / distance_squared;
}

double point_lamp_irradiance(const glm::dvec3& position, double intensity, const glm::dvec3& point,
                             const glm::dvec3& normal) {
  const glm::dvec3 to_point = point - position;
  const double distance_squared = glm::dot(to_point, to_point);
  if (!(distance_squared > 0.0)) return 0.0;
  const double cos_surface = std::min(1.0, -glm::dot(normal, to_point) / std::sqrt(distance_squared));
  return cos_surface > 0.0 ? intensity * cos_surface / distance_squared : 0.0;
}

}  // namespace matgeom
