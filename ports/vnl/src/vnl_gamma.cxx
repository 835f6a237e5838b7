// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/vnl_gamma.h"

#include <cmath>
#include <limits>

inline namespace edgetrack_ports {

namespace {
constexpr int kMaxTerms = 1000;
constexpr double kEps = 1e-15;

/// P(a, x) by its series, for x < a + 1.
double gamma_series(double a, double x) {
  double term = 1.0 / a, sum = term;
  for (int n = 1; n < kMaxTerms; ++n) {
    term *= x / (a + n);
    sum += term;
    if (std::fabs(term) < std::fabs(sum) * kEps) break;
  }
  return sum * std::exp(-x + a * std::log(x) - vnl_log_gamma(a));
}

/// Q(a, x) by Lentz's continued fraction, for x >= a + 1.
double gamma_continued_fraction(double a, double x) {
  const double tiny = std::numeric_limits<double>::min() / kEps;
  double b = x + 1 - a, c = 1 / tiny, d = 1 / b, h = d;
  for (int i = 1; i < kMaxTerms; ++i) {
    const double an = -i * (i - a);
    b += 2;
    d = an * d + b;
    if (std::fabs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::fabs(c) < tiny) c = tiny;
    d = 1 / d;
    const double delta = d * c;
    h *= delta;
    if (std::fabs(delta - 1) < kEps) break;
  }
  return std::exp(-x + a * std::log(x) - vnl_log_gamma(a)) * h;
}
}  // namespace

double vnl_log_gamma(double x) { return std::lgamma(x); }

double vnl_gamma_p(double a, double x) {
  if (x <= 0) return 0;
  return x < a + 1 ? gamma_series(a, x) : 1 - gamma_continued_fraction(a, x);
}

double vnl_gamma_q(double a, double x) {
  if (x <= 0) return 1;
  return x < a + 1 ? 1 - gamma_series(a, x) : gamma_continued_fraction(a, x);
}

double vnl_digamma(double x) {
  double result = 0;
  while (x < 12) {  // psi(x) = psi(x + 1) - 1/x
    result -= 1 / x;
    x += 1;
  }
  const double f = 1 / (x * x);
  // psi(x) ~ ln x - 1/(2x) - 1/(12x^2) + 1/(120x^4) - 1/(252x^6) + 1/(240x^8) - 1/(132x^10)
  return result + std::log(x) - 0.5 / x -
         f * (1.0 / 12 - f * (1.0 / 120 - f * (1.0 / 252 - f * (1.0 / 240 - f * (1.0 / 132)))));
}

}  // inline namespace edgetrack_ports
