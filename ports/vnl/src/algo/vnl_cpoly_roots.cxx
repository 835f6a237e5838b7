// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/algo/vnl_cpoly_roots.h"

#include <algorithm>
#include <cmath>

inline namespace edgetrack_ports {

namespace {

using C = std::complex<double>;

/// p(z) and p'(z) for p = z^N + a[0] z^(N-1) + ... + a[N-1], by Horner.
void evaluate(const vnl_vector<C>& a, C z, C& p, C& dp) {
  p = 1;
  dp = 0;
  for (unsigned k = 0; k < a.size(); ++k) {
    dp = dp * z + p;
    p = p * z + a[k];
  }
}

}  // namespace

vnl_cpoly_roots::vnl_cpoly_roots(const vnl_vector<C>& a) : solns(a.size()), N(a.size()) { compute(a); }

vnl_cpoly_roots::vnl_cpoly_roots(const vnl_vector<double>& a_real, const vnl_vector<double>& a_imag)
    : solns(a_real.size()), N(a_real.size()) {
  vnl_vector<C> a(N);
  for (unsigned k = 0; k < N; ++k) a[k] = C(a_real[k], a_imag[k]);
  compute(a);
}

void vnl_cpoly_roots::compute(const vnl_vector<C>& a) {
  if (N == 0) return;
  // Every root lies within 1 + max |a_k| (Cauchy); start on a circle of half that, off the axes.
  double bound = 0;
  for (unsigned k = 0; k < N; ++k) bound = std::max(bound, std::abs(a[k]));
  const double radius = (1 + bound) / 2, two_pi = 2 * std::acos(-1.0);
  for (unsigned k = 0; k < N; ++k) solns[k] = std::polar(radius, two_pi * (k + 0.25) / N + 0.4);
  constexpr int kMaxIterations = 500;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    double largest_step = 0;
    for (unsigned k = 0; k < N; ++k) {
      C p, dp;
      evaluate(a, solns[k], p, dp);
      if (p == C(0)) continue;
      const C newton = p / dp;
      C repulsion = 0;
      for (unsigned j = 0; j < N; ++j)
        if (j != k) repulsion += C(1) / (solns[k] - solns[j]);
      const C step = newton / (C(1) - newton * repulsion);
      solns[k] -= step;
      largest_step = std::max(largest_step, std::abs(step) / std::max(1.0, std::abs(solns[k])));
    }
    if (largest_step < 1e-15) break;
  }
  for (unsigned k = 0; k < N; ++k) {  // a last Newton step polishes each root
    C p, dp;
    evaluate(a, solns[k], p, dp);
    if (dp != C(0)) solns[k] -= p / dp;
  }
}

}  // inline namespace edgetrack_ports
