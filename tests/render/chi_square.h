#pragma once
// The chi-square distribution for the goodness-of-fit tests of samplers.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

// Regularised upper incomplete gamma function Q(a, x) = Gamma(a, x) / Gamma(a). For x < a + 1 by
// the series P(a, x) = x^a e^-x / Gamma(a + 1) * sum_n x^n / ((a + 1) ... (a + n))
// (Abramowitz & Stegun 6.5.29), Q = 1 - P; otherwise by the continued fraction
// Gamma(a, x) = x^a e^-x / (x + 1 - a - 1 (1 - a) / (x + 3 - a - 2 (2 - a) / (x + 5 - a - ...)))
// (A&S 6.5.31) evaluated with the modified Lentz algorithm.
inline double regularized_upper_gamma(double a, double x) {
  if (x <= 0.0) return 1.0;
  const double log_prefactor = a * std::log(x) - x - std::lgamma(a);
  constexpr double kEpsilon = 1e-15;
  constexpr int kMaxTerms = 100000;
  if (x < a + 1.0) {
    double term = 1.0 / a;
    double sum = term;
    for (int n = 1; n < kMaxTerms && std::abs(term) > kEpsilon * std::abs(sum); ++n) {
      term *= x / (a + n);
      sum += term;
    }
    return 1.0 - sum * std::exp(log_prefactor);
  }
  constexpr double kTiny = 1e-300;
  double b = x + 1.0 - a;
  double c = 1.0 / kTiny;
  double d = 1.0 / b;
  double fraction = d;
  for (int i = 1; i < kMaxTerms; ++i) {
    const double numerator = -i * (i - a);
    b += 2.0;
    d = numerator * d + b;
    if (std::abs(d) < kTiny) d = kTiny;
    c = b + numerator / c;
    if (std::abs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    const double step = c * d;
    fraction *= step;
    if (std::abs(step - 1.0) < kEpsilon) break;
  }
  return fraction * std::exp(log_prefactor);
}

// P(X >= statistic) for X chi-square distributed with the given degrees of freedom.
inline double chi_square_survival(double statistic, int degrees_of_freedom) {
  return regularized_upper_gamma(0.5 * degrees_of_freedom, 0.5 * statistic);
}

struct PearsonTest {
  double statistic = 0.0;
  int degrees_of_freedom = 0;
  double p_value = 0.0;
};

// Pearson's goodness of fit of observed counts to expected ones. Cells expected to get fewer than
// 5 samples are pooled (with the next smallest until the pool reaches 5); the statistic
// sum (O - E)^2 / E then has cells - 1 degrees of freedom. Samples in cells expected to get none
// at all make it infinite.
inline PearsonTest pearson_chi_square(const std::vector<double>& observed, const std::vector<double>& expected) {
  constexpr double kMinExpectedCount = 5.0;
  std::vector<std::size_t> order(observed.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t l, std::size_t r) { return expected[l] < expected[r]; });
  PearsonTest result;
  double pooled_observed = 0.0;
  double pooled_expected = 0.0;
  bool pool_used = false;
  int cells = 0;
  for (std::size_t i : order) {
    if (expected[i] < kMinExpectedCount || (pool_used && pooled_expected < kMinExpectedCount)) {
      pooled_observed += observed[i];
      pooled_expected += expected[i];
      pool_used = true;
      continue;
    }
    result.statistic += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
    ++cells;
  }
  if (pool_used && pooled_expected > 0.0) {
    result.statistic += (pooled_observed - pooled_expected) * (pooled_observed - pooled_expected) / pooled_expected;
    ++cells;
  } else if (pool_used && pooled_observed > 0.0) {
    result.statistic = std::numeric_limits<double>::infinity();
  }
  result.degrees_of_freedom = cells - 1;
  result.p_value = chi_square_survival(result.statistic, result.degrees_of_freedom);
  return result;
}
