// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/algo/vnl_solve_qp.h"

#include <iostream>
#include <vector>

#include "vnl/algo/vnl_svd.h"

inline namespace edgetrack_ports {

bool vnl_solve_qp_with_equality_constraints(const vnl_matrix<double>& H, const vnl_vector<double>& g,
                                            const vnl_matrix<double>& A, const vnl_vector<double>& b,
                                            vnl_vector<double>& x) {
  const unsigned n = H.rows(), m = A.rows();
  vnl_matrix<double> kkt(n + m, n + m, 0.0);
  kkt.update(H, 0, 0);
  kkt.update(A, n, 0);
  kkt.update(A.transpose(), 0, n);
  vnl_vector<double> rhs(n + m);
  for (unsigned i = 0; i < n; ++i) rhs[i] = -g[i];
  for (unsigned i = 0; i < m; ++i) rhs[n + i] = b[i];
  const vnl_svd<double> svd(kkt);
  if (svd.rank() < n + m) return false;
  x = svd.solve(rhs).extract(n);
  return true;
}

bool vnl_solve_qp_zero_sum(const vnl_matrix<double>& H, const vnl_vector<double>& g, vnl_vector<double>& x) {
  return vnl_solve_qp_with_equality_constraints(H, g, vnl_matrix<double>(1, H.rows(), 1.0), vnl_vector<double>(1, 0.0),
                                                x);
}

bool vnl_solve_qp_with_non_neg_constraints(const vnl_matrix<double>& H, const vnl_vector<double>& g,
                                           const vnl_matrix<double>& A, const vnl_vector<double>& b,
                                           vnl_vector<double>& x, double con_tol, bool verbose) {
  const unsigned n = H.rows();
  if ((A * x - b).squared_magnitude() >= con_tol || x.min_value() < 0) {
    if (verbose) std::cerr << "vnl_solve_qp_with_non_neg_constraints: the start x does not satisfy the constraints\n";
    return false;
  }
  std::vector<bool> free(n, true);
  for (unsigned remaining = n; remaining > 0;) {
    // The equality problem on the free variables.
    std::vector<unsigned> index;
    for (unsigned i = 0; i < n; ++i)
      if (free[i]) index.push_back(i);
    const unsigned k = static_cast<unsigned>(index.size());
    vnl_matrix<double> Hf(k, k), Af(A.rows(), k);
    vnl_vector<double> gf(k), xf;
    for (unsigned r = 0; r < k; ++r) {
      gf[r] = g[index[r]];
      for (unsigned c = 0; c < k; ++c) Hf(r, c) = H(index[r], index[c]);
    }
    for (unsigned r = 0; r < A.rows(); ++r)
      for (unsigned c = 0; c < k; ++c) Af(r, c) = A(r, index[c]);
    if (!vnl_solve_qp_with_equality_constraints(Hf, gf, Af, b, xf)) {
      if (verbose) std::cerr << "vnl_solve_qp_with_non_neg_constraints: the equality problem is singular\n";
      return false;
    }
    // Step from x towards xf as far as every variable stays >= 0.
    double step = 1;
    unsigned blocking = k;
    for (unsigned r = 0; r < k; ++r) {
      const double from = x[index[r]], to = xf[r];
      if (to < 0 && from - to > 0 && from / (from - to) < step) {
        step = from / (from - to);
        blocking = r;
      }
    }
    for (unsigned r = 0; r < k; ++r) x[index[r]] += step * (xf[r] - x[index[r]]);
    if (blocking == k) return true;
    x[index[blocking]] = 0;
    free[index[blocking]] = false;
    --remaining;
  }
  return true;
}

bool vnl_solve_qp_non_neg_sum_one(const vnl_matrix<double>& H, const vnl_vector<double>& g, vnl_vector<double>& x,
                                  bool verbose) {
  return vnl_solve_qp_with_non_neg_constraints(H, g, vnl_matrix<double>(1, H.rows(), 1.0), vnl_vector<double>(1, 1.0),
                                               x, 1e-8, verbose);
}

}  // inline namespace edgetrack_ports
