// Sampling of the fast Principled BSDF (libmatrender/src/bsdf): chi-square goodness-of-fit of the
// sampled directions against the code's own pdf (the test of pbrt-v3 and Mitsuba 3), consistency
// of sample() with eval(), reciprocity, normalisation of the pdfs, robustness at the extremes,
// and a white furnace against the reference albedo of shaders_ref.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <vector>

#include "matbase/pi.h"
#include "chi_square.h"
#include "reference_params.h"
#include "principled_lobes.h"
#include "uniform_floats.h"
#include "velvet_condition.h"
#include "bsdf/clearcoat_lobe.h"
#include "bsdf/microfacet_ggx.h"
#include "bsdf/principled.h"
#include "bsdf/principled_diffuse.h"
#include "shaders_ref/directional_albedo.h"
#include "shaders_ref/principled_reference.h"

using matrender::BsdfSample;
using matrender::ClearcoatEstimator;
using matrender::ClearcoatLobe;
using matrender::DiffuseModel;
using matrender::LobeMixture;
using matrender::MaterialParameter;
using matrender::PrincipledInputs;

namespace {

using matbase::kPi;

glm::vec3 direction_with_cosine(float cos_theta) {
  return {std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta)), 0.0f, cos_theta};
}

PrincipledInputs material(glm::vec3 base, float metallic, float roughness, float specular,
                          float specular_tint, DiffuseModel model = DiffuseModel::Principled) {
  PrincipledInputs in;
  in.set(MaterialParameter::BaseColor, base);
  in.set(MaterialParameter::Metallic, metallic);
  in.set(MaterialParameter::Roughness, roughness);
  in.set(MaterialParameter::Specular, specular);
  in.set(MaterialParameter::SpecularTint, specular_tint);
  in.diffuse_model = model;
  return in;
}

PrincipledInputs with_sheen(PrincipledInputs in, float sheen, float sheen_tint) {
  in.set(MaterialParameter::Sheen, sheen);
  in.set(MaterialParameter::SheenTint, sheen_tint);
  return in;
}

PrincipledInputs with_clearcoat(PrincipledInputs in, float clearcoat, float clearcoat_roughness) {
  in.set(MaterialParameter::Clearcoat, clearcoat);
  in.set(MaterialParameter::ClearcoatRoughness, clearcoat_roughness);
  return in;
}

// The Velvet BSDF that glTF's sheen adds beside the Principled one.
PrincipledInputs with_velvet(PrincipledInputs in, glm::vec3 colour, float sigma) {
  in.set(MaterialParameter::VelvetColor, colour);
  in.set(MaterialParameter::VelvetSigma, sigma);
  return in;
}

PrincipledInputs random_material(UniformFloats& rng) {
  PrincipledInputs in;
  in.set(MaterialParameter::BaseColor, glm::vec3{rng.next(), rng.next(), rng.next()});
  in.set(MaterialParameter::Metallic, rng.next() < 0.3f ? 1.0f : rng.next());
  in.set(MaterialParameter::Roughness, 0.02f + 0.98f * rng.next());
  in.set(MaterialParameter::Specular, rng.next());
  in.set(MaterialParameter::SpecularTint, rng.next());
  in.diffuse_model = rng.next() < 0.5f ? DiffuseModel::Principled : DiffuseModel::Lambert;
  in.set(MaterialParameter::Sheen, rng.next() < 0.5f ? 0.0f : rng.next());
  in.set(MaterialParameter::SheenTint, rng.next());
  in.set(MaterialParameter::Clearcoat, rng.next() < 0.5f ? 0.0f : rng.next());
  in.set(MaterialParameter::ClearcoatRoughness, 0.02f + 0.98f * rng.next());
  in.set(MaterialParameter::Transmission, rng.next() < 0.5f ? 0.0f : rng.next());
  in.set(MaterialParameter::TransmissionRoughness, rng.next() < 0.5f ? 0.0f : rng.next());
  in.set(MaterialParameter::Ior, 1.0f + 1.5f * rng.next());
  if (rng.next() < 0.5f) in = with_velvet(in, {rng.next(), rng.next(), rng.next()}, rng.next());
  return in;
}

bool is_finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// --- Charts: coordinates on the unit square for the directions a sampler produces ---------------

struct ChartPoint {
  glm::dvec3 direction;
  double jacobian;  // |d omega / d(x, y)|; 0 where the chart has no direction
};

// The upper hemisphere in (x, y) = (cos theta, phi / 2 pi): Lambert's cylindrical equal-area
// projection, d omega = 2 pi dx dy. Suited to wide lobes.
class CosineAzimuthChart {
 public:
  ChartPoint at(glm::dvec2 xy) const {
    const double sin_theta = std::sqrt(std::max(0.0, 1.0 - xy.x * xy.x));
    const double phi = 2.0 * kPi * xy.y;
    return {{sin_theta * std::cos(phi), sin_theta * std::sin(phi), xy.x}, 2.0 * kPi};
  }
  glm::dvec2 coordinates(const glm::dvec3& w) const { return {w.z, azimuth_fraction(w)}; }

  static double azimuth_fraction(const glm::dvec3& w) {
    const double phi = std::atan2(w.y, w.x);
    return (phi < 0.0 ? phi + 2.0 * kPi : phi) / (2.0 * kPi);
  }
};

// A microfacet normal at chart point (x, y) = (s / (pi/2), phi / 2 pi) of the stretched polar
// angle s, tan(theta_m) = alpha tan(s), and |d omega_m / d(x, y)|.
struct StretchedNormal {
  glm::dvec3 m;
  double jacobian;
};
StretchedNormal stretched_normal(glm::dvec2 xy, double alpha) {
  const double s = 0.5 * kPi * xy.x;
  const double phi = 2.0 * kPi * xy.y;
  const double sin_s = std::sin(s);
  const double cos_s = std::cos(s);
  const double norm2 = cos_s * cos_s + alpha * alpha * sin_s * sin_s;
  const double sin_m = alpha * sin_s / std::sqrt(norm2);
  const double cos_m = cos_s / std::sqrt(norm2);
  const double dtheta_ds = alpha / norm2;
  return {{sin_m * std::cos(phi), sin_m * std::sin(phi), cos_m}, sin_m * dtheta_ds * (0.5 * kPi) * (2.0 * kPi)};
}

// Directions reflected about microfacet normals, wi = 2 (wo.m) m - wo, in (x, y) =
// (s / (pi/2), phi_m / 2 pi) with the stretched polar angle s of the normal, tan(theta_m) =
// alpha tan(s). A GGX lobe of width alpha spreads evenly over s whatever alpha and wo are, so
// peaked lobes at grazing incidence are as finely resolved as rough ones. Every direction above
// the surface has exactly one normal m = normalize(wo + wi) with wo.m > 0; normals with
// wo.m <= 0 have no direction (jacobian 0). d omega_i = 4 (wo.m) d omega_m (Walter et al. 2007,
// eq. 14).
class HalfVectorChart {
 public:
  HalfVectorChart(const glm::vec3& wo, double alpha)
      : wo_(glm::normalize(glm::dvec3(wo))), alpha_(alpha) {}

  ChartPoint at(glm::dvec2 xy) const {
    const StretchedNormal n = stretched_normal(xy, alpha_);
    const double wo_dot_m = glm::dot(wo_, n.m);
    if (wo_dot_m <= 0.0) return {n.m, 0.0};
    return {2.0 * wo_dot_m * n.m - wo_, 4.0 * wo_dot_m * n.jacobian};
  }

  glm::dvec2 coordinates(const glm::dvec3& wi) const {
    const glm::dvec3 m = glm::normalize(wo_ + wi);
    const double sin_m = std::sqrt(m.x * m.x + m.y * m.y);
    const double s = std::atan2(sin_m, alpha_ * m.z);
    return {s / (0.5 * kPi), CosineAzimuthChart::azimuth_fraction(m)};
  }

 private:
  glm::dvec3 wo_;
  double alpha_;
};

// Directions reflected about microfacet normals as HalfVectorChart, with the polar angle of the
// normal taken through the cumulative distribution of Berry's D(m) cos(theta_m) of width a:
// x = 1 - ln(sin^2 + a^2 cos^2) / ln(a^2) (Burley 2012, B.2, eq. 2 inverted). GTR1's mass is
// spread log-uniformly in the slope from a to the horizon, too thinly for the stretched angle of
// HalfVectorChart, which crowds the tail into the last column at small a. In x the mass is
// uniform, and D(m) cos(theta_m) d omega_m = dx dy, so d omega_i = 4 (wo.m) / (D cos) dx dy.
class Gtr1HalfVectorChart {
 public:
  Gtr1HalfVectorChart(const glm::vec3& wo, double a) : wo_(glm::normalize(glm::dvec3(wo))), a2_(a * a) {}

  ChartPoint at(glm::dvec2 xy) const {
    double cos2, sin2;
    if (a2_ >= 1.0) {
      cos2 = 1.0 - xy.x;
      sin2 = xy.x;
    } else {
      const double log_a2 = std::log(a2_);
      cos2 = -std::expm1((1.0 - xy.x) * log_a2) / (1.0 - a2_);
      sin2 = a2_ * std::expm1(-xy.x * log_a2) / (1.0 - a2_);
    }
    const double cos_m = std::sqrt(std::max(0.0, cos2));
    const double sin_m = std::sqrt(std::max(0.0, sin2));
    const double phi = 2.0 * kPi * xy.y;
    const glm::dvec3 m = glm::normalize(glm::dvec3(sin_m * std::cos(phi), sin_m * std::sin(phi), cos_m));
    const double wo_dot_m = glm::dot(wo_, m);
    const double density = shaders_ref::gtr1_ndf(m, std::sqrt(a2_)) * m.z;
    if (wo_dot_m <= 0.0 || !(density > 0.0)) return {m, 0.0};
    return {2.0 * wo_dot_m * m - wo_, 4.0 * wo_dot_m / density};
  }

  glm::dvec2 coordinates(const glm::dvec3& wi) const {
    const glm::dvec3 m = glm::normalize(wo_ + wi);
    const double sin2 = m.x * m.x + m.y * m.y;
    const double x = a2_ >= 1.0 ? sin2 : 1.0 - std::log(sin2 + a2_ * m.z * m.z) / std::log(a2_);
    return {std::clamp(x, 0.0, 1.0), CosineAzimuthChart::azimuth_fraction(m)};
  }

 private:
  glm::dvec3 wo_;
  double a2_;
};

// Directions refracted through microfacet normals into a medium of relative index eta, in the
// stretched polar angle of the normal as HalfVectorChart: wi = refract(wo, m), which exists
// where wo.m > 0 and Snell's law allows it. Every transmitted direction has one generalised half
// vector m = -(wo + eta wi) / |wo + eta wi| facing +Z; d omega_i = (wo.m + eta wi.m)^2 /
// (eta^2 |wi.m|) d omega_m (Walter et al. 2007, eq. 17).
class RefractionChart {
 public:
  RefractionChart(const glm::vec3& wo, double alpha, double eta)
      : wo_(glm::normalize(glm::dvec3(wo))), alpha_(alpha), eta_(eta) {}

  ChartPoint at(glm::dvec2 xy) const {
    const StretchedNormal n = stretched_normal(xy, alpha_);
    const double wo_dot_m = glm::dot(wo_, n.m);
    if (wo_dot_m <= 0.0) return {n.m, 0.0};
    const double sin2_t = (1.0 - wo_dot_m * wo_dot_m) / (eta_ * eta_);
    if (sin2_t >= 1.0) return {n.m, 0.0};
    const double cos_t = std::sqrt(1.0 - sin2_t);
    const glm::dvec3 wi = -wo_ / eta_ + (wo_dot_m / eta_ - cos_t) * n.m;
    const double wi_dot_m = glm::dot(wi, n.m);
    const double denominator = wo_dot_m + eta_ * wi_dot_m;
    return {wi, n.jacobian * denominator * denominator / (eta_ * eta_ * std::abs(wi_dot_m))};
  }

  glm::dvec2 coordinates(const glm::dvec3& wi) const {
    glm::dvec3 m = -(wo_ + eta_ * wi);
    m = glm::normalize(m.z < 0.0 ? -m : m);
    const double sin_m = std::sqrt(m.x * m.x + m.y * m.y);
    return {std::atan2(sin_m, alpha_ * m.z) / (0.5 * kPi), CosineAzimuthChart::azimuth_fraction(m)};
  }

 private:
  glm::dvec3 wo_;
  double alpha_, eta_;
};

// --- Chi-square goodness-of-fit test -------------------------------------------------------------

constexpr int kBinsX = 32;
constexpr int kBinsY = 64;
constexpr int kSampleCount = 1000000;

// Gauss-Legendre 4-point rule on [-1, 1].
constexpr std::array<double, 4> kGaussNodes = {-0.8611363115940526, -0.3399810435848563,
                                               0.3399810435848563, 0.8611363115940526};
constexpr std::array<double, 4> kGaussWeights = {0.3478548451374538, 0.6521451548625461,
                                                 0.6521451548625461, 0.3478548451374538};

struct CellEstimate {
  double probability;
  bool straddles_support;  // the pdf is 0 at some of the cell's nodes and corners, not at all
};

// 4x4 Gauss-Legendre product rule for the integral of pdf(w(x, y)) |dw/d(x, y)| over the cell
// [lo, hi]; the corners are looked at too, to notice a support edge that misses every node.
template <class Chart, class Pdf>
CellEstimate cell_estimate(const Chart& chart, const Pdf& pdf, glm::dvec2 lo, glm::dvec2 hi) {
  const glm::dvec2 half = 0.5 * (hi - lo);
  const glm::dvec2 mid = 0.5 * (hi + lo);
  double sum = 0.0;
  bool zero = false;
  bool positive = false;
  const auto density = [&](glm::dvec2 xy) {
    const ChartPoint p = chart.at(xy);
    const double value = p.jacobian > 0.0 ? pdf(p.direction) * p.jacobian : 0.0;
    if (value > 0.0)
      positive = true;
    else
      zero = true;
    return value;
  };
  for (std::size_t i = 0; i < 4; ++i) {
    for (std::size_t j = 0; j < 4; ++j) {
      sum += kGaussWeights[i] * kGaussWeights[j] *
             density({mid.x + half.x * kGaussNodes[i], mid.y + half.y * kGaussNodes[j]});
    }
  }
  for (const glm::dvec2& corner : {lo, hi, glm::dvec2(lo.x, hi.y), glm::dvec2(hi.x, lo.y)})
    density(corner);
  return {sum * half.x * half.y, zero && positive};
}

// Probability the pdf gives the chart cell [lo, hi] (whole: the cell's own estimate): quadrisected
// while the four quarters disagree with the whole by more than the tolerance (a peak smaller than
// the cell) or the cell straddles the edge of the pdf's support (the horizon), down to
// 1/8 of the cell.
template <class Chart, class Pdf>
double cell_probability(const Chart& chart, const Pdf& pdf, glm::dvec2 lo, glm::dvec2 hi,
                        const CellEstimate& whole, double tolerance, int depth = 3) {
  struct Quarter {
    glm::dvec2 lo, hi;
  };
  const glm::dvec2 mid = 0.5 * (lo + hi);
  const std::array<Quarter, 4> quarters = {Quarter{lo, mid}, Quarter{{mid.x, lo.y}, {hi.x, mid.y}},
                                           Quarter{{lo.x, mid.y}, {mid.x, hi.y}}, Quarter{mid, hi}};
  std::array<CellEstimate, 4> parts{};
  double sum = 0.0;
  for (std::size_t q = 0; q < 4; ++q) {
    parts[q] = cell_estimate(chart, pdf, quarters[q].lo, quarters[q].hi);
    sum += parts[q].probability;
  }
  if (depth == 0 || (!whole.straddles_support && std::abs(sum - whole.probability) <= tolerance))
    return sum;
  double refined = 0.0;
  for (std::size_t q = 0; q < 4; ++q)
    refined += cell_probability(chart, pdf, quarters[q].lo, quarters[q].hi, parts[q],
                                0.25 * tolerance, depth - 1);
  return refined;
}

struct ChiSquareResult {
  double statistic = 0.0;
  int degrees_of_freedom = 0;
  double p_value = 0.0;
  double failed_fraction = 0.0;  // samples the sampler could not make (the failure cell)
  double missing_mass = 0.0;     // 1 - the pdf's integral over the chart (expected failures)
};

// Draws kSampleCount directions with sample(rng) (std::nullopt when the sampler fails), bins
// them on the chart's kBinsX x kBinsY grid plus one cell for failures, and compares with the
// counts expected from pdf: N times its integral over each cell, N times the mass it leaves
// outside the chart for the failure cell (pearson_chi_square).
template <class Chart, class Sampler, class Pdf>
ChiSquareResult chi_square_test(const Chart& chart, Sampler&& sample, const Pdf& pdf,
                                std::uint64_t seed) {
  std::vector<double> observed(kBinsX * kBinsY + 1, 0.0);
  const std::size_t failure_cell = kBinsX * kBinsY;
  UniformFloats rng(seed);
  for (int n = 0; n < kSampleCount; ++n) {
    const std::optional<glm::vec3> wi = sample(rng);
    if (!wi) {
      observed[failure_cell] += 1.0;
      continue;
    }
    const glm::dvec2 xy = chart.coordinates(glm::dvec3(*wi));
    const int ix = std::clamp(static_cast<int>(xy.x * kBinsX), 0, kBinsX - 1);
    const int iy = std::clamp(static_cast<int>(xy.y * kBinsY), 0, kBinsY - 1);
    observed[static_cast<std::size_t>(ix * kBinsY + iy)] += 1.0;
  }

  std::vector<double> expected(observed.size(), 0.0);
  double total_probability = 0.0;
  const double tolerance = 0.01 / kSampleCount;  // 0.01 expected samples per cell
  for (int ix = 0; ix < kBinsX; ++ix) {
    for (int iy = 0; iy < kBinsY; ++iy) {
      const glm::dvec2 lo(static_cast<double>(ix) / kBinsX, static_cast<double>(iy) / kBinsY);
      const glm::dvec2 hi(static_cast<double>(ix + 1) / kBinsX,
                          static_cast<double>(iy + 1) / kBinsY);
      const double probability =
          cell_probability(chart, pdf, lo, hi, cell_estimate(chart, pdf, lo, hi), tolerance);
      expected[static_cast<std::size_t>(ix * kBinsY + iy)] = kSampleCount * probability;
      total_probability += probability;
    }
  }
  expected[failure_cell] = kSampleCount * std::max(0.0, 1.0 - total_probability);

  ChiSquareResult result;
  const PearsonTest pearson = pearson_chi_square(observed, expected);
  result.statistic = pearson.statistic;
  result.degrees_of_freedom = pearson.degrees_of_freedom;
  result.p_value = pearson.p_value;
  result.failed_fraction = observed[failure_cell] / kSampleCount;
  result.missing_mass = 1.0 - total_probability;
  return result;
}

// One lobe's sampling against its own pdf over the shading frame's upper hemisphere, for lobes
// whose normal is tilted off it: directions below the shading plane count as failures.
template <class LobeType>
ChiSquareResult shading_frame_chi_square(const LobeType& lobe, std::uint64_t seed) {
  const auto sample = [&](UniformFloats& rng) -> std::optional<glm::vec3> {
    matrender::LobeSample s;
    if (!lobe.sample(rng.next2(), &s) || s.wi.z <= 0.0f) return std::nullopt;
    return s.wi;
  };
  const auto pdf = [&](const glm::dvec3& wi) {
    float p = 0.0f;
    lobe.eval(glm::vec3(wi), &p);
    return wi.z > 0.0 ? static_cast<double>(p) : 0.0;
  };
  return chi_square_test(CosineAzimuthChart(), sample, pdf, seed);
}

// The chi-square tests of this file, for the Bonferroni correction of the significance level.
constexpr std::array<float, 5> kGgxRoughness = {0.02f, 0.1f, 0.3f, 0.6f, 1.0f};
constexpr std::array<float, 4> kGgxCosO = {1.0f, 0.7f, 0.3f, 0.05f};

struct MixtureCase {
  const char* name;
  PrincipledInputs inputs;
  float cos_o;
};
const std::array<MixtureCase, 9> kMixtureCases = {{
    {"dielectric", material({0.8f, 0.3f, 0.2f}, 0.0f, 0.3f, 0.5f, 0.0f), 0.8f},
    {"metallic 1", material({0.9f, 0.6f, 0.3f}, 1.0f, 0.5f, 0.5f, 0.0f), 0.4f},
    {"mixed", material({0.2f, 0.5f, 0.9f}, 0.5f, 0.15f, 0.8f, 0.5f), 0.15f},
    // Fabric: diffuse, sheen and a rough specular lobe, at a grazing view where sheen is strong.
    {"sheen, grazing", with_sheen(material({0.3f, 0.2f, 0.6f}, 0.0f, 0.8f, 0.5f, 0.0f), 1.0f, 0.5f), 0.15f},
    {"sheen, half metal", with_sheen(material({0.7f, 0.5f, 0.2f}, 0.5f, 0.4f, 0.5f, 0.0f), 0.6f, 1.0f), 0.6f},
    // Lacquered wood: diffuse, a rough specular lobe and a glossy clearcoat.
    {"clearcoat", with_clearcoat(material({0.5f, 0.3f, 0.1f}, 0.0f, 0.6f, 0.5f, 0.0f), 1.0f, 0.1f), 0.5f},
    {"clearcoat, grazing", with_clearcoat(material({0.2f, 0.6f, 0.3f}, 0.0f, 0.3f, 0.5f, 0.0f), 0.7f, 0.3f), 0.1f},
    // glTF's sheen: a velvet beside a rough dielectric, and alone (black base, no specular) at grazing.
    {"velvet over diffuse", with_velvet(material({0.3f, 0.3f, 0.5f}, 0.0f, 0.7f, 0.5f, 0.0f), {0.8f, 0.6f, 0.4f}, 0.35f),
     0.3f},
    {"velvet alone, grazing", with_velvet(material(glm::vec3(0.0f), 0.0f, 0.5f, 0.0f, 0.0f), glm::vec3(0.5f), 1.0f),
     0.1f},
}};
constexpr int kMixtureCharts = 2;

// The clearcoat lobe alone, both estimators, and once with its normal tilted off the shading normal.
constexpr std::array<float, 4> kClearcoatRoughness = {0.03f, 0.1f, 0.3f, 1.0f};
constexpr int kClearcoatTests = 2 * static_cast<int>(kClearcoatRoughness.size() * kGgxCosO.size()) + 1;

// The glass refraction alone: entering water, glass and diamond, and leaving glass (total
// internal reflection beyond 42 degrees).
constexpr std::array<float, 4> kRefractionEta = {1.33f, 1.5f, 2.4f, 1.0f / 1.5f};
constexpr std::array<float, 3> kRefractionRoughness = {0.02f, 0.3f, 1.0f};
constexpr std::array<float, 3> kRefractionCosO = {1.0f, 0.5f, 0.1f};
constexpr int kRefractionTests =
    static_cast<int>(kRefractionEta.size() * kRefractionRoughness.size() * kRefractionCosO.size());

// The velvet lobe alone with its normal tilted off the shading normal.
constexpr int kVelvetTests = 1;

constexpr int kChiSquareTestCount = 1 + static_cast<int>(kGgxRoughness.size() * kGgxCosO.size()) +
                                    static_cast<int>(kMixtureCases.size()) * kMixtureCharts + kClearcoatTests +
                                    kRefractionTests + kVelvetTests;
constexpr double kSignificance = 0.01 / kChiSquareTestCount;

void report(const ChiSquareResult& r) {
  INFO("chi^2 = " << r.statistic << ", dof = " << r.degrees_of_freedom << ", p = " << r.p_value
                  << " (reject below " << kSignificance << "); failed samples " << r.failed_fraction
                  << ", pdf mass outside the chart " << r.missing_mass);
  CHECK(r.p_value >= kSignificance);
}

}  // namespace

TEST_CASE("Regularised incomplete gamma matches closed forms", "[render]") {
  for (double x : {0.1, 0.5, 1.0, 3.0, 10.0, 40.0}) {
    CAPTURE(x);
    CHECK(regularized_upper_gamma(1.0, x) == Approx(std::exp(-x)).epsilon(1e-12));
    CHECK(regularized_upper_gamma(0.5, x) == Approx(std::erfc(std::sqrt(x))).epsilon(1e-10));
    // Integer a: Q(n, x) = e^-x sum_{k<n} x^k / k!
    double term = 1.0;
    double sum = 1.0;
    for (int k = 1; k < 5; ++k) {
      term *= x / k;
      sum += term;
    }
    CHECK(regularized_upper_gamma(5.0, x) == Approx(std::exp(-x) * sum).epsilon(1e-10));
  }
  // Large degrees of freedom: the median of chi^2_k is close to k (1 - 2 / (9k))^3.
  const int k = 2000;
  const double median = k * std::pow(1.0 - 2.0 / (9.0 * k), 3.0);
  CHECK(chi_square_survival(median, k) == Approx(0.5).margin(1e-3));
}

TEST_CASE("Cosine-weighted diffuse sampling fits diffuse_pdf (chi-square)", "[render]") {
  const glm::vec3 wo = direction_with_cosine(0.6f);
  const auto sample = [](UniformFloats& rng) -> std::optional<glm::vec3> {
    const glm::vec3 wi = matrender::diffuse_sample(rng.next2());
    if (wi.z <= 0.0f) return std::nullopt;
    return wi;
  };
  const auto pdf = [&](const glm::dvec3& wi) {
    return static_cast<double>(matrender::diffuse_pdf(wo, glm::vec3(wi)));
  };
  report(chi_square_test(CosineAzimuthChart(), sample, pdf, 0x5eed0001));
}

TEST_CASE("GGX visible-normal sampling fits ggx_reflection_pdf (chi-square)", "[render]") {
  std::uint64_t seed = 0x5eed0100;
  for (float roughness : kGgxRoughness) {
    for (float cos_o : kGgxCosO) {
      CAPTURE(roughness, cos_o);
      const float alpha = roughness * roughness;
      const glm::vec3 wo = direction_with_cosine(cos_o);
      const auto sample = [&](UniformFloats& rng) -> std::optional<glm::vec3> {
        const glm::vec3 m = matrender::ggx_sample_visible_normal(wo, alpha, rng.next2());
        const glm::vec3 wi = matrender::reflect_about(wo, m);
        if (wi.z <= 0.0f) return std::nullopt;  // below the horizon: the sample is lost
        return wi;
      };
      const auto pdf = [&](const glm::dvec3& wi) {
        return static_cast<double>(matrender::ggx_reflection_pdf(wo, glm::vec3(wi), alpha));
      };
      report(chi_square_test(HalfVectorChart(wo, alpha), sample, pdf, ++seed));
    }
  }
}

TEST_CASE("Clearcoat sampling fits its pdf (chi-square)", "[render]") {
  // Integral: GTR1 normals, against the lobe's own pdf. Cycles34: GGX visible normals of alpha =
  // clearcoat_roughness^2, which is what Cycles draws (its reported pdf is another one, so only
  // the draw can be tested against a density).
  std::uint64_t seed = 0x5eed0150;
  for (const ClearcoatEstimator estimator : {ClearcoatEstimator::Integral, ClearcoatEstimator::Cycles34}) {
    for (float roughness : kClearcoatRoughness) {
      for (float cos_o : kGgxCosO) {
        const bool cycles = estimator == ClearcoatEstimator::Cycles34;
        CAPTURE(cycles, roughness, cos_o);
        const float alpha = roughness * roughness;
        const glm::vec3 wo = direction_with_cosine(cos_o);
        const ClearcoatLobe lobe(0.25f, alpha, estimator, wo, glm::vec3(0.0f, 0.0f, 1.0f));
        const auto sample = [&](UniformFloats& rng) -> std::optional<glm::vec3> {
          matrender::LobeSample s;
          if (!lobe.sample(rng.next2(), &s)) return std::nullopt;
          return s.wi;
        };
        const auto pdf = [&](const glm::dvec3& wi) {
          if (cycles) return static_cast<double>(matrender::ggx_reflection_pdf(wo, glm::vec3(wi), alpha));
          float p = 0.0f;
          lobe.eval(glm::vec3(wi), &p);
          return static_cast<double>(p);
        };
        if (cycles)
          report(chi_square_test(HalfVectorChart(wo, alpha), sample, pdf, ++seed));
        else
          report(chi_square_test(Gtr1HalfVectorChart(wo, alpha), sample, pdf, ++seed));
      }
    }
  }
  // Under a normal map the lobe's normal is not +Z: sampling and pdf must turn with it.
  const glm::vec3 tilted_normal = glm::normalize(glm::vec3(0.3f, -0.2f, 1.0f));
  const glm::vec3 wo = glm::normalize(glm::vec3(-0.4f, 0.1f, 0.8f));
  const ClearcoatLobe lobe(0.25f, 0.36f, ClearcoatEstimator::Integral, wo, tilted_normal);
  INFO("tilted normal");
  report(shading_frame_chi_square(lobe, ++seed));
}

TEST_CASE("Velvet sampling fits its pdf with the lobe's normal tilted (chi-square)", "[render]") {
  // Uniform over the hemisphere of the lobe's normal, which a normal map tilts off the shading
  // normal: the directions below the shading plane are the chart's failures.
  const glm::vec3 tilted_normal = glm::normalize(glm::vec3(-0.25f, 0.3f, 1.0f));
  const glm::vec3 wo = glm::normalize(glm::vec3(0.5f, 0.2f, 0.6f));
  const matrender::VelvetLobe lobe(glm::vec3(0.7f), 0.4f, wo, tilted_normal);
  report(shading_frame_chi_square(lobe, 0x5eed0170));
}

TEST_CASE("GGX refraction sampling fits its pdf (chi-square)", "[render]") {
  // Samples lost to total internal reflection (a microfacet wo cannot refract through) are the
  // failures the chart's missing mass predicts.
  std::uint64_t seed = 0x5eed0180;
  for (float eta : kRefractionEta) {
    for (float roughness : kRefractionRoughness) {
      for (float cos_o : kRefractionCosO) {
        CAPTURE(eta, roughness, cos_o);
        const float alpha = roughness * roughness;
        const glm::vec3 wo = direction_with_cosine(cos_o);
        const matrender::GgxTransmissionLobe lobe(glm::vec3(1.0f), eta, alpha, wo);
        const auto sample = [&](UniformFloats& rng) -> std::optional<glm::vec3> {
          matrender::LobeSample s;
          if (!lobe.sample(rng.next2(), &s)) return std::nullopt;
          return s.wi;
        };
        const auto pdf = [&](const glm::dvec3& wi) {
          float p = 0.0f;
          lobe.eval(glm::vec3(wi), &p);
          return static_cast<double>(p);
        };
        report(chi_square_test(RefractionChart(wo, alpha, eta), sample, pdf, ++seed));
      }
    }
  }
}

TEST_CASE("GGX refraction obeys the eta^2 rule of radiance: f(wo, wi) / eta^2 = f(wi, wo) from the far side",
          "[render]") {
  // Veach 1997, eq. 5.13 with the relative index eta of wi's medium over wo's: seen from wi the
  // index is 1 / eta, and the BTDFs of the two directions differ by eta^2.
  UniformFloats rng(0x5eed0190);
  int checked = 0;
  for (int n = 0; n < 20000; ++n) {
    const float eta = kRefractionEta[static_cast<size_t>(n) % kRefractionEta.size()];
    const float alpha = 0.02f + 0.98f * rng.next();
    const glm::vec3 wo = random_upper_direction(rng);
    glm::vec3 wi = random_upper_direction(rng);
    wi.z = -wi.z;
    const matrender::GgxTransmissionLobe forward(glm::vec3(1.0f), eta, alpha, wo);
    const matrender::GgxTransmissionLobe backward(glm::vec3(1.0f), 1.0f / eta, alpha, -wi);
    float pdf;
    const double f_forward = forward.eval(wi, &pdf).x / std::abs(wi.z);
    const double f_backward = backward.eval(-wo, &pdf).x / wo.z;
    if (f_forward == 0.0 && f_backward == 0.0) continue;
    CAPTURE(eta, alpha, wo.z, wi.z);
    // 2e-4 relative for float rounding, plus 1e-5 absolute far in the lobe's tail, where D of the
    // half vector computed from each side in float differs by up to 1e-3 relative (values ~1e-6,
    // against peaks of 1e2 to 1e4).
    CHECK(std::abs(f_forward / (eta * eta) - f_backward) <= 2e-4 * f_backward + 1e-5);
    ++checked;
  }
  // About a quarter of random pairs cannot refract into each other (no microfacet faces both).
  CHECK(checked > 4000);
}

TEST_CASE("principled_bsdf's sample fits the mixture pdf of eval (chi-square)", "[render]") {
  std::uint64_t seed = 0x5eed0200;
  for (const MixtureCase& c : kMixtureCases) {
    CAPTURE(c.name);
    const glm::vec3 wo = direction_with_cosine(c.cos_o);
    const LobeMixture bsdf = principled_bsdf(c.inputs, wo);
    const auto sample = [&](UniformFloats& rng) -> std::optional<glm::vec3> {
      const float u_lobe = rng.next();
      BsdfSample s;
      if (!bsdf.sample(u_lobe, rng.next2(), &s)) return std::nullopt;
      return s.wi;
    };
    const auto pdf = [&](const glm::dvec3& wi) {
      float p = 0.0f;
      bsdf.eval(glm::vec3(wi), &p);
      return static_cast<double>(p);
    };
    const double alpha = static_cast<double>(c.inputs.scalar(MaterialParameter::Roughness)) * c.inputs.scalar(MaterialParameter::Roughness);
    {
      INFO("chart: cos theta x azimuth");
      report(chi_square_test(CosineAzimuthChart(), sample, pdf, ++seed));
    }
    // The half-vector chart resolves glossy peaks; it resolves the horizon, where a uniform pdf
    // jumps to 0 along a curve across its cells, too coarsely for a mixture without them.
    if (matrender::is_glossy(bsdf.flags())) {
      INFO("chart: half vector");
      report(chi_square_test(HalfVectorChart(wo, alpha), sample, pdf, ++seed));
    }
  }
}

TEST_CASE("principled_bsdf's sample weight is eval / pdf at the sampled direction", "[render]") {
  UniformFloats rng(0x5eed0300);
  int checked = 0;
  for (int n = 0; n < 20000; ++n) {
    const PrincipledInputs in = random_material(rng);
    const glm::vec3 wo = random_upper_direction(rng);
    const LobeMixture bsdf = principled_bsdf(in, wo);
    const float u_lobe = rng.next();
    BsdfSample s;
    if (!bsdf.sample(u_lobe, rng.next2(), &s)) continue;
    float pdf = 0.0f;
    const glm::vec3 value = bsdf.eval(s.wi, &pdf);
    REQUIRE(pdf > 0.0f);
    CHECK(s.pdf == Approx(pdf).epsilon(1e-6));
    for (int k = 0; k < 3; ++k)
      CHECK(s.weight[k] == Approx(value[k] / pdf).epsilon(1e-5).margin(1e-7));
    ++checked;
  }
  CHECK(checked > 15000);
}

TEST_CASE("BSDF values are reciprocal in wo and wi", "[render]") {
  // eval_*() return f cos(theta_i), so f(wo, wi) = eval_wo(wi) / cos_i and f(wi, wo) =
  // eval_wi(wo) / cos_o. The two evaluation orders round differently: 1e-5 relative, plus what
  // the specular lobe's Fresnel argument loses: wi.h and wo.h are equal in exact arithmetic but
  // h = normalize(wo + wi) carries a relative error ~ eps / |wo + wi| = eps / (2 cos_h), and the
  // interpolated Fresnel's F(cos) - F0 cancels to ~1e-7 absolute, i.e. 1e-6 times the BRDF with
  // F = 1 (metallic 1, base 1).
  UniformFloats rng(0x5eed0400);
  for (int n = 0; n < 20000; ++n) {
    // Not glass: Cycles weighs the glass's reflection and refraction by F(N.V), which only
    // depends on wo (the refraction has its own rule, the eta^2 test above).
    PrincipledInputs in = random_material(rng);
    in.set(MaterialParameter::Transmission, 0.0f);
    const glm::vec3 wo = random_upper_direction(rng);
    const glm::vec3 wi = random_upper_direction(rng);
    const LobeMixture forward = principled_bsdf(in, wo);
    const LobeMixture backward = principled_bsdf(in, wi);
    const glm::vec3 spec_forward = specular_value(forward, wi) / wi.z;
    const glm::vec3 spec_backward = specular_value(backward, wo) / wo.z;
    const glm::vec3 diffuse_forward = diffuse_value(forward, wi) / wi.z;
    const glm::vec3 diffuse_backward = diffuse_value(backward, wo) / wo.z;

    shaders_ref::PrincipledParams fresnel_one = reference_params(in);
    fresnel_one.base_color = glm::dvec3(1.0);
    fresnel_one.metallic = 1.0;
    const glm::dvec3 wo_d = glm::normalize(glm::dvec3(wo));
    const glm::dvec3 wi_d = glm::normalize(glm::dvec3(wi));
    const double f_without_fresnel = shaders_ref::specular_brdf(fresnel_one, wo_d, wi_d).x;
    const double cos_h = glm::length(wo_d + wi_d) / 2.0;
    for (int k = 0; k < 3; ++k) {
      INFO("model " << (in.diffuse_model == DiffuseModel::Lambert ? "Lambert" : "principled")
                    << ", roughness " << in.scalar(MaterialParameter::Roughness) << ", metallic " << in.scalar(MaterialParameter::Metallic) << ", cos_o "
                    << wo.z << ", cos_i " << wi.z << ", cos_h " << cos_h);
      const double spec_tolerance =
          (1e-5 + 1e-6 / cos_h) * std::abs(spec_backward[k]) + 1e-6 * f_without_fresnel;
      CHECK(std::abs(spec_forward[k] - spec_backward[k]) <= spec_tolerance);
      // The sheen's (1 - wi.h)^5 and the velvet's D(h) share the half vector's error.
      const bool half_vector_lobe = in.scalar(MaterialParameter::Sheen) > 0.0f ||
                                    in.color(MaterialParameter::VelvetColor) != glm::vec3(0.0f);
      // Both orders are float evaluations: twice the velvet's own error.
      const double velvet_error = 2.0 * velvet_condition(in, wo_d, wi_d);
      const double diffuse_tolerance =
          (1e-5 + (half_vector_lobe ? 1e-6 / cos_h : 0.0) + velvet_error) * std::abs(diffuse_backward[k]) + 1e-12;
      CHECK(std::abs(diffuse_forward[k] - diffuse_backward[k]) <= diffuse_tolerance);
    }
  }
}

TEST_CASE("Sampling pdfs integrate to at most 1 over the sphere", "[render]") {
  SECTION("GGX reflection pdf: the mass reflected above the horizon") {
    for (float roughness : kGgxRoughness) {
      for (float cos_o : kGgxCosO) {
        CAPTURE(roughness, cos_o);
        const float alpha = roughness * roughness;
        const glm::vec3 wo = direction_with_cosine(cos_o);
        const glm::dvec3 wo_d = glm::normalize(glm::dvec3(wo));
        const double integral = shaders_ref::integrate_over_sphere(
            [&](const glm::dvec3& wi) {
              return static_cast<double>(matrender::ggx_reflection_pdf(wo, glm::vec3(wi), alpha));
            },
            {-wo_d.x, -wo_d.y, wo_d.z}, 2.0 * alpha * cos_o);
        // Reference: the reflection pdf G1(wo) D(m) / (4 cos_o) (Heitz 2018, eq. 17 with the
        // reflection Jacobian) over the directions above the horizon.
        const double above_horizon = shaders_ref::integrate_over_reflected_directions(
            [&](const glm::dvec3& wi) {
              const glm::dvec3 m = glm::normalize(wo_d + wi);
              return shaders_ref::ggx_smith_g1(wo_d, alpha) * shaders_ref::ggx_ndf(m, alpha) /
                     (4.0 * wo_d.z);
            },
            wo_d, alpha);
        // 2e-5: three times the largest quadrature error of integrate_over_sphere seen on these
        // cases (6e-6, the narrow lobe cut by the horizon at roughness 0.02, cos_o 0.05).
        CHECK(integral <= 1.0 + 2e-5);
        CHECK(integral == Approx(above_horizon).margin(2e-5));
        if (roughness <= 0.5f) CHECK(integral >= 0.9);
        // At alpha = 1, D = 1/pi and the visible-normal mass above the horizon is
        // 2 / (pi (1 + cos_o)) * int (wo.m) dm = 1 / (1 + cos_o), since dm = dwi / (4 wo.m).
        if (roughness == 1.0f) CHECK(integral == Approx(1.0 / (1.0 + wo_d.z)).margin(2e-5));
      }
    }
  }
  SECTION("Mixture pdf of principled_bsdf's eval") {
    for (const MixtureCase& c : kMixtureCases) {
      CAPTURE(c.name);
      const glm::vec3 wo = direction_with_cosine(c.cos_o);
      const LobeMixture bsdf = principled_bsdf(c.inputs, wo);
      const double alpha = static_cast<double>(c.inputs.scalar(MaterialParameter::Roughness)) * c.inputs.scalar(MaterialParameter::Roughness);
      const double integral = shaders_ref::integrate_over_sphere(
          [&](const glm::dvec3& wi) {
            float p = 0.0f;
            bsdf.eval(glm::vec3(wi), &p);
            return static_cast<double>(p);
          },
          {-wo.x, -wo.y, wo.z}, 2.0 * alpha * c.cos_o);
      CHECK(integral <= 1.0 + 2e-5);
      CHECK(integral >= 0.9);
    }
  }
}

TEST_CASE("eval and sample stay finite at extreme inputs", "[render]") {
  const std::array<float, 7> roughness_values = {0.0f, 1e-4f, 0.0177f, 0.0178f, 0.02f, 0.5f, 1.0f};
  const std::array<float, 3> metallic_values = {0.0f, 0.5f, 1.0f};
  const std::array<float, 3> specular_values = {0.0f, 0.5f, 1.0f};
  const std::array<glm::vec3, 3> base_values = {glm::vec3(0.0f), glm::vec3(1.0f),
                                                glm::vec3(0.9f, 0.1f, 0.0f)};
  const std::array<float, 5> cos_values = {1.0f, 0.5f, 1e-3f, 1e-6f, 0.0f};
  const std::array<float, 3> u_edges = {0.0f, 0.5f, 1.0f - 0x1p-24f};
  UniformFloats rng(0x5eed0500);
  for (float roughness : roughness_values)
    for (float metallic : metallic_values)
      for (float specular : specular_values)
        for (const glm::vec3& base : base_values)
          for (DiffuseModel model : {DiffuseModel::Principled, DiffuseModel::Lambert})
            for (float cos_o : cos_values) {
              // The clearcoat follows the specular and roughness values, with Cycles' estimator
              // for one diffuse model; the glass weighs 1 - specular, with an index from water to
              // past diamond, left through the back face for the Lambert model (total internal
              // reflection at grazing); the opacity is 1 - specular / 2.
              PrincipledInputs in =
                  with_clearcoat(material(base, metallic, roughness, specular, 0.5f, model), specular, roughness);
              in.set(MaterialParameter::Transmission, 1.0f - specular);
              in.set(MaterialParameter::Ior, 1.0f + 2.0f * metallic + 0.33f * specular);
              in.set(MaterialParameter::Alpha, 1.0f - 0.5f * specular);
              // A velvet of the base colour, its width the roughness (0: Cycles' floor 0.01).
              in = with_velvet(in, base, roughness);
              const bool lambert = model == DiffuseModel::Lambert;
              const glm::vec3 wo = direction_with_cosine(cos_o);
              const LobeMixture bsdf = principled_bsdf(
                  in, wo, lambert ? ClearcoatEstimator::Cycles34 : ClearcoatEstimator::Integral, !lambert);
              INFO("roughness " << roughness << ", metallic " << metallic << ", specular "
                                << specular << ", cos_o " << cos_o << (lambert ? ", leaving glass" : ""));
              std::vector<glm::vec3> directions = {direction_with_cosine(1.0f),
                                                   direction_with_cosine(1e-6f),
                                                   direction_with_cosine(0.0f),
                                                   {-wo.x, -wo.y, wo.z},
                                                   wo,
                                                   {0.0f, 0.0f, -1.0f}};
              for (int n = 0; n < 8; ++n) {
                glm::vec3 w = random_upper_direction(rng);
                if (n % 2) w.z = -w.z;
                directions.push_back(w);
              }
              for (const glm::vec3& wi : directions) {
                float pdf = -1.0f;
                const glm::vec3 value = bsdf.eval(wi, &pdf);
                CHECK(is_finite(value));
                CHECK((std::isfinite(pdf) && pdf >= 0.0f));
              }
              std::vector<std::array<float, 3>> uniforms;
              for (float a : u_edges)
                for (float b : u_edges)
                  for (float c : u_edges) uniforms.push_back({a, b, c});
              for (int n = 0; n < 8; ++n) uniforms.push_back({rng.next(), rng.next(), rng.next()});
              for (const auto& u : uniforms) {
                BsdfSample s;
                if (!bsdf.sample(u[0], {u[1], u[2]}, &s)) continue;
                CHECK(is_finite(s.wi));
                CHECK(is_finite(s.weight));
                CHECK((std::isfinite(s.pdf) && s.pdf >= 0.0f));
                CHECK(std::abs(glm::length(s.wi) - 1.0f) < 1e-4f);
              }
            }
}

TEST_CASE("White furnace: mean sample weight equals the reference directional albedo", "[render]") {
  // Mean of N sample weights (failed samples count 0) against the shaders_ref quadrature. The
  // tolerance is 4 standard errors from the sample variance, plus what the variance cannot see:
  // an outcome rarer than 1/N (a sample lost below the horizon at low roughness, probability
  // ~4e-6 at roughness 0.02 and cos_o 0.1) is absent from N samples, and its probability is below
  // 3/N at 95 % confidence (the "rule of three"), so it may shift the mean by up to
  // 3 max|weight| / N; plus 1e-6 for the float rounding of the weights (a zero-variance
  // estimator, Lambert, must still come out as 1).
  constexpr int kSamples = 100000;
  const auto check_mean_weight = [](const PrincipledInputs& in, float cos_o, std::uint64_t seed,
                                    ClearcoatEstimator estimator, double reference, bool front_face = true) {
    const glm::vec3 wo = direction_with_cosine(cos_o);
    const LobeMixture bsdf = principled_bsdf(in, wo, estimator, front_face);
    UniformFloats rng(seed);
    double sum = 0.0;
    double sum_sq = 0.0;
    double max_weight = 0.0;
    for (int n = 0; n < kSamples; ++n) {
      const float u_lobe = rng.next();
      BsdfSample s;
      const double w = bsdf.sample(u_lobe, rng.next2(), &s) ? static_cast<double>(s.weight.y) : 0.0;
      sum += w;
      sum_sq += w * w;
      max_weight = std::max(max_weight, std::abs(w));
    }
    const double mean = sum / kSamples;
    const double variance = std::max(0.0, (sum_sq - kSamples * mean * mean) / (kSamples - 1));
    const double standard_error = std::sqrt(variance / kSamples);
    INFO("roughness " << in.scalar(MaterialParameter::Roughness) << ", metallic " << in.scalar(MaterialParameter::Metallic)
                      << ", transmission " << in.scalar(MaterialParameter::Transmission) << " ior "
                      << in.scalar(MaterialParameter::Ior) << (front_face ? " entering" : " leaving")
                      << ", clearcoat " << in.scalar(MaterialParameter::Clearcoat) << " roughness "
                      << in.scalar(MaterialParameter::ClearcoatRoughness) << ", cos_o " << cos_o << ": mean weight "
                      << mean << " +- " << standard_error << ", reference " << reference);
    CHECK(std::abs(mean - reference) <= 4.0 * standard_error + 3.0 * max_weight / kSamples + 1e-6);
  };
  const auto check_furnace = [&](const PrincipledInputs& in, float cos_o, std::uint64_t seed) {
    const glm::dvec3 wo = glm::normalize(glm::dvec3(direction_with_cosine(cos_o)));
    check_mean_weight(in, cos_o, seed, ClearcoatEstimator::Integral,
                      shaders_ref::directional_albedo(reference_params(in), wo).y);
  };

  std::uint64_t seed = 0x5eed0600;
  const std::array<float, 3> cos_values = {1.0f, 0.5f, 0.1f};
  const std::array<float, 6> roughness_values = {0.02f, 0.1f, 0.3f, 0.5f, 0.8f, 1.0f};
  for (float cos_o : cos_values) {
    check_furnace(material(glm::vec3(1.0f), 0.0f, 0.5f, 0.0f, 0.0f, DiffuseModel::Lambert), cos_o,
                  ++seed);
    for (float roughness : roughness_values) {
      // Principled diffuse alone (specular 0 and metallic 0 make no specular lobe).
      check_furnace(material(glm::vec3(1.0f), 0.0f, roughness, 0.0f, 0.0f), cos_o, ++seed);
      // GGX alone with F = 1 (cspec0 = base = 1).
      check_furnace(material(glm::vec3(1.0f), 1.0f, roughness, 0.5f, 0.0f), cos_o, ++seed);
      // Diffuse and sheen (sheen adds to the diffuse, as in Cycles: more than 1 at grazing).
      check_furnace(with_sheen(material(glm::vec3(1.0f), 0.0f, roughness, 0.0f, 0.0f), 1.0f, 0.0f), cos_o, ++seed);
      // The velvet alone (black base, no specular), its width following the roughness.
      check_furnace(with_velvet(material(glm::vec3(0.0f), 0.0f, 0.5f, 0.0f, 0.0f), glm::vec3(1.0f),
                                std::max(roughness, 0.2f)),
                    cos_o, ++seed);
      // Clearcoat alone (black base, no specular), and on top of a white diffuse.
      check_furnace(with_clearcoat(material(glm::vec3(0.0f), 0.0f, 0.5f, 0.0f, 0.0f), 1.0f, roughness), cos_o, ++seed);
      check_furnace(with_clearcoat(material(glm::vec3(1.0f), 0.0f, 0.5f, 0.5f, 0.0f), 0.5f, roughness), cos_o, ++seed);
    }
  }

  // Glass of base colour 1 and no specular tint, entering and leaving. Smooth: the reflection
  // takes F(cos_o) and the refraction 1 - F, exactly 1 together (also past the critical angle,
  // where the reflection takes all and the refraction samples nothing). Rough: single-scatter
  // GGX loses what scatters more than once, so at most 1, and what the reference integrates.
  for (const float ior : {1.33f, 1.5f, 2.4f}) {
    for (const bool front_face : {true, false}) {
      for (const float cos_o : {1.0f, 0.7f, 0.5f, 0.1f}) {
        for (const float roughness : {0.0f, 0.1f, 0.5f, 1.0f}) {
          PrincipledInputs glass = material(glm::vec3(1.0f), 0.0f, roughness, 0.5f, 0.0f);
          glass.set(MaterialParameter::Transmission, 1.0f);
          glass.set(MaterialParameter::Ior, ior);
          const double reference =
              roughness == 0.0f ? 1.0 : [&] {
                shaders_ref::PrincipledParams p = reference_params(glass);
                p.front_face = front_face;
                return shaders_ref::directional_albedo(p, glm::normalize(glm::dvec3(direction_with_cosine(cos_o)))).y;
              }();
          CHECK(reference <= 1.0 + 1e-6);
          check_mean_weight(glass, cos_o, ++seed, ClearcoatEstimator::Integral, reference, front_face);
        }
      }
    }
  }

  // Cycles 3.4's clearcoat estimator: directions drawn from GGX visible normals of alpha a =
  // clearcoat_roughness^2, p(wi) = G1_a(wo) D_a(m) / (4 cos_o), weighted by f cos / q with the
  // reported q = G1_0.25(wo) D_GTR1(m) / (4 cos_o). Its mean is the integral of
  // (f cos / q) p, computed here from shaders_ref's independent GGX and GTR1, not the integral of
  // f cos: the bias docs/conventions.md describes, which the Cycles34 estimator must reproduce.
  for (float roughness : {0.05f, 0.1f, 0.3f, 0.8f}) {
    for (float cos_o : cos_values) {
      const PrincipledInputs in = with_clearcoat(material(glm::vec3(0.0f), 0.0f, 0.5f, 0.0f, 0.0f), 1.0f, roughness);
      const shaders_ref::PrincipledParams p = reference_params(in);
      const glm::dvec3 wo = glm::normalize(glm::dvec3(direction_with_cosine(cos_o)));
      const double a = shaders_ref::ggx_alpha(roughness);
      const double cycles_mean = shaders_ref::integrate_over_reflected_directions(
          [&](const glm::dvec3& wi) {
            const glm::dvec3 m = glm::normalize(wo + wi);
            const double drawn = shaders_ref::ggx_smith_g1(wo, a) * shaders_ref::ggx_ndf(m, a) / (4.0 * wo.z);
            const double reported = shaders_ref::ggx_smith_g1(wo, 0.25) * shaders_ref::gtr1_ndf(m, a) / (4.0 * wo.z);
            return shaders_ref::clearcoat_brdf(p, wo, wi).x * wi.z / reported * drawn;
          },
          wo, a);
      const double integral = shaders_ref::lobe_albedos(p, wo).clearcoat.x;
      CAPTURE(roughness, cos_o, cycles_mean, integral);
      // The bias is real where the lobe is narrow: Cycles' estimate is off the integral.
      if (roughness <= 0.1f) CHECK(std::abs(cycles_mean / integral - 1.0) > 0.05);
      check_mean_weight(in, cos_o, ++seed, ClearcoatEstimator::Cycles34, cycles_mean);
    }
  }
}
