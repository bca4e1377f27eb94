#pragma once
// The chi-square distribution for the goodness-of-fit tests of samplers.
#include <cmath>

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
