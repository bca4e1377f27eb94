#pragma once
// Deterministic double-precision quadrature over directions: the directional albedo of the
// reference Principled BSDF and integrals of arbitrary functions over the sphere and over
// microfacet normals. Nested, globally adaptive Gauss-Kronrod (7-15) rules in coordinates chosen
// so that every integrand is smooth on its domain; accurate to better than 1e-5 relative for
// roughness in [0.02, 1] and cos_o in [0.02, 1].
#include <functional>

#include <glm/glm.hpp>

#include "shaders_ref/principled_reference.h"

namespace shaders_ref {

using DirectionFunction = std::function<double(const glm::dvec3&)>;

struct LobeAlbedos {
  glm::dvec3 diffuse{0.0};
  glm::dvec3 sheen{0.0};
  glm::dvec3 specular{0.0};
  glm::dvec3 clearcoat{0.0};
  glm::dvec3 glass_reflection{0.0};
  glm::dvec3 glass_refraction{0.0};  // over the lower hemisphere
  glm::dvec3 velvet{0.0};
};

// Directional albedo of each lobe, a(wo) = integral over the upper hemisphere of
// f(wo, wi) cos(theta_i) dwi, per RGB channel. wo is a unit vector with wo.z > 0.
// The diffuse, sheen and velvet lobes are integrated over wi in spherical coordinates. The specular lobe is integrated
// over the half vector m with wi = reflect(wo, m), dwi = 4 (wo.m) dm (Walter et al. 2007,
// eq. 14), in the "stretched" polar angle s with tan(theta_m) = alpha tan(s): the GGX
// distribution is spread evenly over s in [0, pi/2) whatever alpha is, and the horizon
// wi.z > 0 becomes the closed-form limit s < s_max(phi), so the integrand is smooth. The
// clearcoat and the glass reflection are integrated the same way (the clearcoat with its GTR1
// width for alpha); the glass refraction over the sphere around the refracted direction
// (integrate_over_sphere, about 1e-6 absolute).
LobeAlbedos lobe_albedos(const PrincipledParams& p, const glm::dvec3& wo);

// The sum of the lobes' albedos: reflected plus transmitted.
glm::dvec3 directional_albedo(const PrincipledParams& p, const glm::dvec3& wo);

// Integral of f(w) over the whole unit sphere (e.g. a pdf, to check it integrates to at most 1).
// f may be discontinuous (a pdf cut at the horizon) and may peak sharply around peak_axis
// (unit) with an angular width of about peak_width radians: the polar angle about peak_axis is
// split at peak_width * 2^k before the adaptive refinement. Absolute accuracy about 1e-6.
double integrate_over_sphere(const DirectionFunction& f, const glm::dvec3& peak_axis,
                             double peak_width);

// Integral of g(wi) over the upper hemisphere (wi.z > 0) for functions concentrated around the
// mirror direction of wo like a GGX reflection lobe of width alpha > 0 (e.g. its pdf): the
// half-vector parametrisation of lobe_albedos, exact at the horizon.
double integrate_over_reflected_directions(const DirectionFunction& g, const glm::dvec3& wo,
                                           double alpha);

// Integral of g(m) over the upper hemisphere of microfacet normals (m.z > 0), in the stretched
// polar angle of GGX width alpha > 0 (see lobe_albedos), for functions concentrated like D(m).
double integrate_over_microfacet_normals(const DirectionFunction& g, double alpha);

}  // namespace shaders_ref
