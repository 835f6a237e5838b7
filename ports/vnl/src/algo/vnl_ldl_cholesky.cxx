// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/algo/vnl_ldl_cholesky.h"

#include <cmath>
#include <iostream>

inline namespace edgetrack_ports {

vnl_ldl_cholesky::vnl_ldl_cholesky(const vnl_matrix<double>& M, Operation mode)
    : L_(M.rows(), M.cols(), 0.0), d_(M.rows(), 0.0) {
  const unsigned n = M.rows();
  if (n > 0 && std::fabs(M(0, n - 1) - M(n - 1, 0)) > 1e-8)
    std::cerr << "vnl_ldl_cholesky: WARNING: non-symmetric: " << M << '\n';
  // Column by column: d_j = M_jj - sum_k L_jk^2 d_k, L_ij = (M_ij - sum_k L_ik L_jk d_k) / d_j.
  for (unsigned j = 0; j < n; ++j) {
    double dj = M(j, j);
    for (unsigned k = 0; k < j; ++k) dj -= L_(j, k) * L_(j, k) * d_[k];
    if (!(dj > 0) && num_dims_rank_def_ == 0) num_dims_rank_def_ = static_cast<int>(j) + 1;
    d_[j] = dj;
    L_(j, j) = 1;
    for (unsigned i = j + 1; i < n; ++i) {
      double lij = M(i, j);
      for (unsigned k = 0; k < j; ++k) lij -= L_(i, k) * L_(j, k) * d_[k];
      L_(i, j) = dj != 0 ? lij / dj : 0;
    }
  }
  if (mode == verbose && num_dims_rank_def_ != 0)
    std::cerr << "vnl_ldl_cholesky: " << num_dims_rank_def_ << " dimensions of non-posdeffness\n";
  if (mode == estimate_condition) {
    if (num_dims_rank_def_ != 0) {
      rcond_ = 0;
    } else {
      const double norm = M.operator_one_norm(), inverse_norm = inverse().operator_one_norm();
      rcond_ = 1 / (norm * inverse_norm);
    }
  }
}

void vnl_ldl_cholesky::inplace_solve(double* x) const {
  const unsigned n = d_.size();
  for (unsigned i = 0; i < n; ++i)  // L y = b
    for (unsigned k = 0; k < i; ++k) x[i] -= L_(i, k) * x[k];
  for (unsigned i = 0; i < n; ++i) x[i] /= d_[i];  // D z = y
  for (unsigned i = n; i-- > 0;)                   // L^T x = z
    for (unsigned k = i + 1; k < n; ++k) x[i] -= L_(k, i) * x[k];
}

vnl_vector<double> vnl_ldl_cholesky::solve(const vnl_vector<double>& b) const {
  vnl_vector<double> x = b;
  inplace_solve(x.data_block());
  return x;
}

void vnl_ldl_cholesky::solve(const vnl_vector<double>& b, vnl_vector<double>* x) const { *x = solve(b); }

void vnl_ldl_cholesky::solve_lx(vnl_vector<double>& y) {
  for (unsigned i = 0; i < y.size(); ++i)
    for (unsigned k = 0; k < i; ++k) y[i] -= L_(i, k) * y[k];
}

double vnl_ldl_cholesky::determinant() const {
  double det = 1;
  for (double d : d_) det *= d;
  return det;
}

void vnl_ldl_cholesky::rank1_update(const vnl_vector<double>& v) {
  const unsigned n = d_.size();
  vnl_vector<double> w = v;
  double alpha = 1;
  for (unsigned j = 0; j < n; ++j) {
    const double p = w[j];
    const double d_new = d_[j] + alpha * p * p;
    const double beta = p * alpha / d_new;
    alpha = d_[j] * alpha / d_new;
    d_[j] = d_new;
    for (unsigned r = j + 1; r < n; ++r) {
      w[r] -= p * L_(r, j);
      L_(r, j) += beta * w[r];
    }
  }
}

void vnl_ldl_cholesky::update(const vnl_matrix<double>& W) {
  for (unsigned c = 0; c < W.cols(); ++c) rank1_update(W.get_column(c));
}

vnl_matrix<double> vnl_ldl_cholesky::inverse() const {
  const unsigned n = d_.size();
  vnl_matrix<double> inv(n, n);
  vnl_vector<double> column(n);
  for (unsigned c = 0; c < n; ++c) {
    column.fill(0);
    column[c] = 1;
    inplace_solve(column.data_block());
    inv.set_column(c, column);
  }
  return inv;
}

double vnl_ldl_cholesky::xt_m_inv_x(const vnl_vector<double>& x) const {
  // x^T L^-T D^-1 L^-1 x = sum_i y_i^2 / d_i with L y = x.
  vnl_vector<double> y = x;
  for (unsigned i = 0; i < y.size(); ++i)
    for (unsigned k = 0; k < i; ++k) y[i] -= L_(i, k) * y[k];
  double sum = 0;
  for (unsigned i = 0; i < y.size(); ++i) sum += y[i] * y[i] / d_[i];
  return sum;
}

double vnl_ldl_cholesky::xt_m_x(const vnl_vector<double>& x) const {
  // x^T L D L^T x = sum_i d_i y_i^2 with y = L^T x.
  const unsigned n = d_.size();
  double sum = 0;
  for (unsigned i = 0; i < n; ++i) {
    double yi = x[i];
    for (unsigned k = i + 1; k < n; ++k) yi += L_(k, i) * x[k];
    sum += d_[i] * yi * yi;
  }
  return sum;
}

}  // inline namespace edgetrack_ports
