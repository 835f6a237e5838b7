// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/algo/vnl_sparse_lu.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>

inline namespace edgetrack_ports {

vnl_sparse_lu::vnl_sparse_lu(const vnl_sparse_matrix<double>& M, operation mode) : A_(M), mode_(mode) {
  if (M.rows() != M.cols()) std::cerr << "vnl_sparse_lu: the matrix is not square\n";
}

void vnl_sparse_lu::decompose_matrix() {
  const unsigned n = A_.rows();
  std::vector<std::map<unsigned, double>> rows(n);
  for (unsigned r = 0; r < n; ++r)
    for (const auto& entry : A_.get_row(r))
      if (entry.second != 0) rows[r][entry.first] = entry.second;
  std::vector<unsigned> order(n);  // order[k]: the A row now in position k
  for (unsigned k = 0; k < n; ++k) order[k] = k;
  L_.assign(n, {});
  sign_ = 1;
  singular_ = false;
  for (unsigned k = 0; k < n; ++k) {
    // The candidates: remaining rows with an entry in column k.
    double largest = 0;
    for (unsigned p = k; p < n; ++p) {
      auto it = rows[order[p]].find(k);
      if (it != rows[order[p]].end()) largest = std::max(largest, std::fabs(it->second));
    }
    if (largest <= absolute_thresh_ || largest == 0) {
      singular_ = true;
      continue;
    }
    // The current diagonal if allowed and large enough, else the sparsest large-enough row.
    auto entry = [&](unsigned p) {
      auto it = rows[order[p]].find(k);
      return it == rows[order[p]].end() ? 0.0 : std::fabs(it->second);
    };
    unsigned chosen = n;
    if (diag_pivoting_ && entry(k) >= pivot_thresh_ * largest && entry(k) > 0) chosen = k;
    if (chosen == n) {
      for (unsigned p = k; p < n; ++p) {
        const double a = entry(p);
        if (a == 0 || a < pivot_thresh_ * largest) continue;
        if (chosen == n || rows[order[p]].size() < rows[order[chosen]].size() ||
            (rows[order[p]].size() == rows[order[chosen]].size() && a > entry(chosen)))
          chosen = p;
      }
    }
    if (chosen != k) {
      std::swap(order[k], order[chosen]);
      std::swap(L_[k], L_[chosen]);
      sign_ = -sign_;
    }
    const std::map<unsigned, double>& pivot_row = rows[order[k]];
    const double pivot = pivot_row.at(k);
    for (unsigned p = k + 1; p < n; ++p) {
      std::map<unsigned, double>& row = rows[order[p]];
      auto it = row.find(k);
      if (it == row.end()) continue;
      const double factor = it->second / pivot;
      row.erase(it);
      L_[p][k] = factor;
      for (auto e = pivot_row.upper_bound(k); e != pivot_row.end(); ++e) row[e->first] -= factor * e->second;
    }
  }
  U_.assign(n, {});
  perm_ = order;
  largest_ = 0;
  for (unsigned k = 0; k < n; ++k) {
    U_[k] = rows[order[k]];
    for (const auto& e : U_[k]) largest_ = std::max(largest_, std::fabs(e.second));
  }
  if (singular_ && (mode_ == verbose || mode_ == estimate_condition_verbose))
    std::cerr << "vnl_sparse_lu: the matrix is singular\n";
  factored_ = true;
}

vnl_vector<double> vnl_sparse_lu::solve(const vnl_vector<double>& b) {
  vnl_vector<double> x;
  solve(b, &x);
  return x;
}

void vnl_sparse_lu::solve(const vnl_vector<double>& b, vnl_vector<double>* x) {
  if (!factored_) decompose_matrix();
  const unsigned n = A_.rows();
  vnl_vector<double> y(n);
  for (unsigned k = 0; k < n; ++k) {  // L y = P b
    double v = b[perm_[k]];
    for (const auto& e : L_[k]) v -= e.second * y[e.first];
    y[k] = v;
  }
  x->set_size(n);
  for (unsigned k = n; k-- > 0;) {  // U x = y
    double v = y[k], diagonal = 0;
    for (const auto& e : U_[k]) {
      if (e.first == k)
        diagonal = e.second;
      else
        v -= e.second * (*x)[e.first];
    }
    (*x)[k] = v / diagonal;
  }
}

vnl_vector<double> vnl_sparse_lu::solve_transpose(const vnl_vector<double>& b) {
  vnl_vector<double> x;
  solve_transpose(b, &x);
  return x;
}

void vnl_sparse_lu::solve_transpose(const vnl_vector<double>& b, vnl_vector<double>* x) {
  if (!factored_) decompose_matrix();
  // A^T = U^T L^T P: U^T z = b (forward, by columns of U), L^T w = z (backward), x = P^T w.
  const unsigned n = A_.rows();
  vnl_vector<double> z = b;
  for (unsigned k = 0; k < n; ++k) {
    const double diagonal = U_[k].at(k);
    z[k] /= diagonal;
    for (auto e = U_[k].upper_bound(k); e != U_[k].end(); ++e) z[e->first] -= e->second * z[k];
  }
  for (unsigned k = n; k-- > 0;)
    for (const auto& e : L_[k]) z[e.first] -= e.second * z[k];
  x->set_size(n);
  for (unsigned k = 0; k < n; ++k) (*x)[perm_[k]] = z[k];
}

double vnl_sparse_lu::determinant() {
  if (!factored_) decompose_matrix();
  if (singular_) return 0;
  double det = sign_;
  for (unsigned k = 0; k < A_.rows(); ++k) det *= U_[k].at(k);
  return det;
}

bool vnl_sparse_lu::est_condition() {
  if (!factored_) decompose_matrix();
  condition_computed_ = true;
  if (singular_) return false;
  const unsigned n = A_.rows();
  double norm = 0;
  for (unsigned r = 0; r < n; ++r) {
    double sum = 0;
    for (const auto& e : A_.get_row(r)) sum += std::fabs(e.second);
    norm = std::max(norm, sum);
  }
  // |A^-1|_inf is the largest row sum of A^-1, i.e. the largest column sum of A^-T.
  double inverse_norm = 0;
  vnl_vector<double> unit(n, 0.0), column;
  for (unsigned c = 0; c < n; ++c) {
    unit[c] = 1;
    solve_transpose(unit, &column);
    unit[c] = 0;
    inverse_norm = std::max(inverse_norm, column.one_norm());
  }
  rcond_ = 1 / (norm * inverse_norm);
  return true;
}

double vnl_sparse_lu::rcond() {
  if (mode_ != estimate_condition && mode_ != estimate_condition_verbose) return 0;
  if (!condition_computed_) est_condition();
  return rcond_;
}

double vnl_sparse_lu::max_error_bound() {
  const double r = rcond();
  if (!(r > 0)) return 0;
  return A_.rows() * std::numeric_limits<double>::epsilon() * largest_ / r;
}

}  // inline namespace edgetrack_ports
