#pragma once
// Irradiance that Cycles' lamps give a small surface (a grey card, a photometer): the closed forms
// every meter of the project uses, on plain values so that any lamp type can call them.
// Radiance and intensity come in whatever units the caller weighs them in (W, or W times a colour's
// luminance); the irradiance comes out in the same units per m^2.
#include <array>

#include <glm/glm.hpp>

namespace matgeom {

// The projected solid angle, through the hemisphere about unit `normal`, of the polygon with
// corners `corners` (relative to the receiving point): the irradiance per unit radiance of a
// uniform Lambertian emitter of that shape. Lambert's formula, E / L = 1/2 sum_i angle(v_i, v_i+1)
// n . unit(v_i x v_i+1), after clipping the polygon to the hemisphere, where it holds.
double quad_projected_solid_angle(const std::array<glm::dvec3, 4>& corners, const glm::dvec3& normal);

// A one-sided rectangle lamp (Cycles' area lamp: emitting down its local -Z, uniform radiance
// `radiance`), size_x along its +X and size_y along its +Y: the irradiance at `point` on a surface
// with unit normal `normal`.
double rect_lamp_irradiance(const glm::dmat4& light_to_world, double size_x, double size_y, double radiance,
                            const glm::dvec3& point, const glm::dvec3& normal);

// A radius-0 Cycles spot lamp at `position` along unit `forward` with on-axis intensity
// `intensity` (P / 4 pi, not concentrated into the cone): E = I a(t) cos / d^2 with
// a(t) = cos t smoothstep((cos t - cos(angle / 2)) / ((1 - cos(angle / 2)) blend)) inside the cone,
// t the angle from the axis, cos that between the normal and the direction to the lamp.
double spot_lamp_irradiance(const glm::dvec3& position, const glm::dvec3& forward, double spot_angle, double blend,
                            double intensity, const glm::dvec3& point, const glm::dvec3& normal);

// A point lamp of intensity `intensity`: E = I cos / d^2 (0 at the lamp itself).
double point_lamp_irradiance(const glm::dvec3& position, double intensity, const glm::dvec3& point,
                             const glm::dvec3& normal);

}  // namespace matgeom
