#include "shaders_ref/directional_albedo.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "matbase/pi.h"

namespace shaders_ref {
namespace {

using matbase::kPi;

// --- One-dimensional globally adaptive Gauss-Kronrod quadrature ------------------------------

// The 15-point Kronrod rule on [-1, 1] (nodes +-x_k) and the 7-point Gauss rule it extends, whose
// nodes are x_1, x_3, x_5 and x_7 = 0 (Kronrod 1965; Piessens et al. 1983, QUADPACK).
constexpr std::array<double, 8> kKronrodNodes = {
    0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
    0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
    0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
    0.207784955007898467600689403773245, 0.0};
constexpr std::array<double, 8> kKronrodWeights = {
    0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
    0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
    0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
    0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
constexpr std::array<double, 4> kGaussWeights = {
    0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
    0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

double magnitude(double v) { return std::abs(v); }
double magnitude(const glm::dvec3& v) {
  return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

template <class Value>
struct Panel {
  double a, b;
  Value integral;
  double error;  // |Kronrod - Gauss| on the panel
};

template <class Value, class Integrand>
Panel<Value> gauss_kronrod_panel(const Integrand& f, double a, double b) {
  const double half = 0.5 * (b - a);
  const double mid = 0.5 * (a + b);
  const Value centre = f(mid);
  Value kronrod = centre * kKronrodWeights[7];
  Value gauss = centre * kGaussWeights[3];
  for (std::size_t k = 0; k < 7; ++k) {
    const double dx = half * kKronrodNodes[k];
    const Value pair = f(mid - dx) + f(mid + dx);
    kronrod += pair * kKronrodWeights[k];
    if (k % 2 == 1) gauss += pair * kGaussWeights[k / 2];
  }
  return {a, b, kronrod * half, magnitude(kronrod - gauss) * std::abs(half)};
}

struct Tolerance {
  double absolute;
  double relative;
  std::size_t max_panels;  // budget that bounds the work when the tolerance cannot be met
};

// Integral of f over [breakpoints.front(), breakpoints.back()], starting from one panel per
// breakpoint interval and bisecting the panel with the largest error estimate until the summed
// estimate is below max(absolute, relative * |integral|) (the QUADPACK QAG strategy).
template <class Value, class Integrand>
Value integrate_adaptive(const Integrand& f, const std::vector<double>& breakpoints,
                         const Tolerance& tolerance) {
  std::vector<Panel<Value>> panels;
  for (std::size_t i = 0; i + 1 < breakpoints.size(); ++i) {
    if (breakpoints[i + 1] > breakpoints[i])
      panels.push_back(gauss_kronrod_panel<Value>(f, breakpoints[i], breakpoints[i + 1]));
  }
  while (true) {
    Value total(0.0);
    double error = 0.0;
    for (const Panel<Value>& panel : panels) {
      total += panel.integral;
      error += panel.error;
    }
    const double goal = std::max(tolerance.absolute, tolerance.relative * magnitude(total));
    if (error <= goal || panels.size() >= tolerance.max_panels) return total;
    const auto worst = std::max_element(
        panels.begin(), panels.end(),
        [](const Panel<Value>& l, const Panel<Value>& r) { return l.error < r.error; });
    const double a = worst->a;
    const double b = worst->b;
    const double mid = 0.5 * (a + b);
    *worst = gauss_kronrod_panel<Value>(f, a, mid);
    panels.push_back(gauss_kronrod_panel<Value>(f, mid, b));
  }
}

// Tolerance for an inner integral whose result is integrated again over an outer interval of
// the given length: its errors add up over that length (and |Kronrod - Gauss| overestimates the
// error of the Kronrod result by orders of magnitude for smooth integrands).
Tolerance inner_tolerance(const Tolerance& outer, double outer_length) {
  return {0.5 * outer.absolute / outer_length, 0.5 * outer.relative, outer.max_panels};
}

// Accuracy of the albedo integrals: far below the 1e-5 relative the tests rely on.
constexpr Tolerance kAlbedoTolerance{1e-10, 1e-9, 400};
// Accuracy of the general-purpose integrals, whose integrands may be float code with
// discontinuities: about 1e-6 absolute for a pdf, well above the float rounding noise (1e-7
// relative) that no refinement can remove.
constexpr Tolerance kSphereTolerance{1e-6, 1e-6, 100};

const std::vector<double> kAzimuthBreakpoints = {-kPi, -0.5 * kPi, 0.0, 0.5 * kPi, kPi};

// --- Coordinates -------------------------------------------------------------------------------

glm::dvec3 spherical_direction(double sin_theta, double cos_theta, double phi) {
  return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
}

// Orthonormal basis (t, b, n) around the unit vector n (Gram-Schmidt against the coordinate axis
// least aligned with n).
struct Basis {
  glm::dvec3 t, b, n;
  glm::dvec3 to_world(const glm::dvec3& v) const { return v.x * t + v.y * b + v.z * n; }
};
Basis basis_around(const glm::dvec3& n) {
  const glm::dvec3 helper = std::abs(n.x) < 0.5 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  const glm::dvec3 t = glm::normalize(helper - glm::dot(helper, n) * n);
  return {t, glm::cross(n, t), n};
}

// The stretched polar angle s of a GGX lobe of width alpha: tan(theta_m) = alpha tan(s), so the
// slope distribution D(m) cos(theta_m) dm = sin(2 s) ds dphi / (2 pi) (Walter et al. 2007,
// eq. 35-36: its sampling formula with xi_1 = sin^2 s). Written with sin s and cos s, finite up
// to s = pi/2.
struct StretchedAngle {
  double sin_theta, cos_theta;  // of the microfacet normal
  double dtheta_ds;             // alpha / (cos^2 s + alpha^2 sin^2 s)
};
StretchedAngle stretched_angle(double s, double alpha) {
  const double sin_s = std::sin(s);
  const double cos_s = std::cos(s);
  const double norm2 = cos_s * cos_s + alpha * alpha * sin_s * sin_s;
  const double norm = std::sqrt(norm2);
  return {alpha * sin_s / norm, cos_s / norm, alpha / norm2};
}

// Breakpoints 0, atan(1), atan(2), atan(4), ... < s_end, s_end in the stretched angle, i.e. where
// tan(theta_m) = alpha, 2 alpha, 4 alpha, ...: geometric in the microfacet slope, so that features
// of an integrand at a fixed slope (the horizon, wo.m = 0) are resolved for any alpha, although
// the stretched angle crowds them into a sliver below pi/2 when alpha is small.
std::vector<double> stretched_breakpoints(double s_end) {
  std::vector<double> breakpoints = {0.0};
  for (double t = 1.0; std::atan(t) < s_end; t *= 2.0) breakpoints.push_back(std::atan(t));
  breakpoints.push_back(s_end);
  return breakpoints;
}

// Largest stretched angle whose half vector m (at azimuth phi relative to wo) still reflects wo
// above the surface. With tau = tan(theta_m), wi.z = 2 (wo.m) cos(theta_m) - cos_o > 0 reads
// cos_o tau^2 - 2 sin_o cos(phi) tau - cos_o < 0; tau_max is the positive root, written with the
// form that does not cancel (the roots' product is -1).
double stretched_horizon_limit(double sin_o, double cos_o, double phi, double alpha) {
  const double b = sin_o * std::cos(phi);
  const double root = std::sqrt(b * b + cos_o * cos_o);
  const double tau_max = b >= 0.0 ? (b + root) / cos_o : cos_o / (root - b);
  return std::atan(tau_max / alpha);
}

// --- Lobe albedos ------------------------------------------------------------------------------

// Integral of brdf(p, wo, wi) cos(theta_i) over the upper hemisphere in spherical coordinates,
// for lobes smooth over it (diffuse, sheen, velvet).
glm::dvec3 hemisphere_albedo(glm::dvec3 (*brdf)(const PrincipledParams&, const glm::dvec3&, const glm::dvec3&),
                             const PrincipledParams& p, const glm::dvec3& wo) {
  const double phi_o = std::atan2(wo.y, wo.x);
  const Tolerance inner = inner_tolerance(kAlbedoTolerance, 2.0 * kPi);
  const std::vector<double> polar_range = {0.0, 0.5 * kPi};
  // a = int dphi int f(wo, wi) cos(theta) sin(theta) dtheta
  const auto over_polar_angle = [&](double phi) {
    const auto integrand = [&](double theta) {
      const double sin_t = std::sin(theta);
      const double cos_t = std::cos(theta);
      const glm::dvec3 wi = spherical_direction(sin_t, cos_t, phi_o + phi);
      return brdf(p, wo, wi) * (cos_t * sin_t);
    };
    return integrate_adaptive<glm::dvec3>(integrand, polar_range, inner);
  };
  return integrate_adaptive<glm::dvec3>(over_polar_angle, kAzimuthBreakpoints, kAlbedoTolerance);
}

// Integral of g(wi) over the upper hemisphere in half-vector coordinates (phi relative to wo's
// azimuth, stretched angle s of m up to the horizon limit), wi = 2 (wo.m) m - wo:
// int g(wi) dwi = int dphi int g(wi) |dwi/dm| sin(theta_m) dtheta_m/ds ds with
// |dwi/dm| = 4 (wo.m) (Walter et al. 2007, eq. 14).
template <class Value>
Value integrate_over_reflections(const std::function<Value(const glm::dvec3&)>& g,
                                 const glm::dvec3& wo, double alpha) {
  const double phi_o = std::atan2(wo.y, wo.x);
  const double cos_o = wo.z;
  const double sin_o = std::sqrt(std::max(0.0, 1.0 - cos_o * cos_o));
  const Tolerance inner = inner_tolerance(kAlbedoTolerance, 2.0 * kPi);
  const auto over_stretched_angle = [&](double phi) {
    const auto integrand = [&](double s) {
      const StretchedAngle m_angle = stretched_angle(s, alpha);
      const glm::dvec3 m = spherical_direction(m_angle.sin_theta, m_angle.cos_theta, phi_o + phi);
      const double wo_dot_m = glm::dot(wo, m);
      const glm::dvec3 wi = 2.0 * wo_dot_m * m - wo;
      if (wi.z <= 0.0 || wo_dot_m <= 0.0) return Value(0.0);
      return g(wi) * (4.0 * wo_dot_m * m_angle.sin_theta * m_angle.dtheta_ds);
    };
    const double s_max = stretched_horizon_limit(sin_o, cos_o, phi, alpha);
    return integrate_adaptive<Value>(integrand, stretched_breakpoints(s_max), inner);
  };
  return integrate_adaptive<Value>(over_stretched_angle, kAzimuthBreakpoints, kAlbedoTolerance);
}

glm::dvec3 specular_albedo(const PrincipledParams& p, const glm::dvec3& wo) {
  if (!has_specular_lobe(p)) return glm::dvec3(0.0);
  return integrate_over_reflections<glm::dvec3>(
      [&](const glm::dvec3& wi) { return specular_brdf(p, wo, wi) * wi.z; }, wo,
      ggx_alpha(p.roughness));
}

glm::dvec3 clearcoat_albedo(const PrincipledParams& p, const glm::dvec3& wo) {
  if (p.clearcoat <= 0.0) return glm::dvec3(0.0);
  return integrate_over_reflections<glm::dvec3>(
      [&](const glm::dvec3& wi) { return clearcoat_brdf(p, wo, wi) * wi.z; }, wo,
      ggx_alpha(p.clearcoat_roughness));
}

glm::dvec3 glass_reflection_albedo(const PrincipledParams& p, const glm::dvec3& wo) {
  if (p.transmission <= 0.0) return glm::dvec3(0.0);
  return integrate_over_reflections<glm::dvec3>(
      [&](const glm::dvec3& wi) { return glass_reflection_brdf(p, wo, wi) * wi.z; }, wo, ggx_alpha(p.roughness));
}

// Per channel, over the sphere around the direction wo refracts to through the macro normal (or
// its mirror image below the surface where it cannot refract).
glm::dvec3 glass_refraction_albedo(const PrincipledParams& p, const glm::dvec3& wo) {
  if (p.transmission <= 0.0) return glm::dvec3(0.0);
  const double eta = glass_eta(p);
  const double sin2_t = (1.0 - wo.z * wo.z) / (eta * eta);
  const glm::dvec3 peak = sin2_t < 1.0 ? glm::normalize(glm::dvec3(-wo.x / eta, -wo.y / eta, -std::sqrt(1.0 - sin2_t)))
                                       : glm::dvec3(wo.x, wo.y, -wo.z);
  const double roughness = 1.0 - (1.0 - p.roughness) * (1.0 - p.transmission_roughness);
  const double width = 2.0 * ggx_alpha(roughness);
  glm::dvec3 albedo(0.0);
  for (int c = 0; c < 3; ++c)
    albedo[c] = integrate_over_sphere(
        [&](const glm::dvec3& wi) { return glass_refraction_btdf(p, wo, wi)[c] * std::abs(wi.z); }, peak, width);
  return albedo;
}

}  // namespace

LobeAlbedos lobe_albedos(const PrincipledParams& p, const glm::dvec3& wo) {
  if (wo.z <= 0.0) return {};
  const glm::dvec3 sheen = p.sheen > 0.0 ? hemisphere_albedo(sheen_brdf, p, wo) : glm::dvec3(0.0);
  const glm::dvec3 velvet = p.velvet_color != glm::dvec3(0.0) ? hemisphere_albedo(velvet_brdf, p, wo) : glm::dvec3(0.0);
  return {hemisphere_albedo(diffuse_brdf, p, wo), sheen, specular_albedo(p, wo), clearcoat_albedo(p, wo),
          glass_reflection_albedo(p, wo), glass_refraction_albedo(p, wo), velvet};
}

glm::dvec3 directional_albedo(const PrincipledParams& p, const glm::dvec3& wo) {
  const LobeAlbedos albedos = lobe_albedos(p, wo);
  return albedos.diffuse + albedos.sheen + albedos.specular + albedos.clearcoat + albedos.glass_reflection +
         albedos.glass_refraction + albedos.velvet;
}

double integrate_over_sphere(const DirectionFunction& f, const glm::dvec3& peak_axis,
                             double peak_width) {
  const Basis basis = basis_around(peak_axis);
  // Polar breakpoints 0, w, 2w, 4w, ... < pi: the first panels resolve the peak.
  std::vector<double> polar_breakpoints = {0.0};
  for (double theta = peak_width; theta > 0.0 && theta < kPi; theta *= 2.0)
    polar_breakpoints.push_back(theta);
  polar_breakpoints.push_back(kPi);

  const Tolerance inner = inner_tolerance(kSphereTolerance, kPi);
  const auto over_azimuth = [&](double theta) {
    const double sin_t = std::sin(theta);
    const double cos_t = std::cos(theta);
    const auto integrand = [&](double phi) {
      return f(basis.to_world(spherical_direction(sin_t, cos_t, phi))) * sin_t;
    };
    return integrate_adaptive<double>(integrand, kAzimuthBreakpoints, inner);
  };
  return integrate_adaptive<double>(over_azimuth, polar_breakpoints, kSphereTolerance);
}

double integrate_over_reflected_directions(const DirectionFunction& g, const glm::dvec3& wo,
                                           double alpha) {
  if (wo.z <= 0.0) return 0.0;
  return integrate_over_reflections<double>(g, wo, alpha);
}

double integrate_over_microfacet_normals(const DirectionFunction& g, double alpha) {
  const Tolerance inner = inner_tolerance(kAlbedoTolerance, 2.0 * kPi);
  // The slope doubles from panel to panel up to 1e4 (theta_m = 89.994 degrees); one panel takes
  // the rest of the hemisphere.
  std::vector<double> breakpoints = stretched_breakpoints(std::atan(1e4 / alpha));
  breakpoints.push_back(0.5 * kPi);
  const auto over_stretched_angle = [&](double phi) {
    const auto integrand = [&](double s) {
      const StretchedAngle m_angle = stretched_angle(s, alpha);
      const glm::dvec3 m = spherical_direction(m_angle.sin_theta, m_angle.cos_theta, phi);
      return g(m) * m_angle.sin_theta * m_angle.dtheta_ds;
    };
    return integrate_adaptive<double>(integrand, breakpoints, inner);
  };
  return integrate_adaptive<double>(over_stretched_angle, kAzimuthBreakpoints, kAlbedoTolerance);
}

}  // namespace shaders_ref
