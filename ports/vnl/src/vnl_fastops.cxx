// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/vnl_fastops.h"

#include <cassert>

inline namespace edgetrack_ports {

namespace {
/// X(i, j) += sign * sum_k a(i, k) b(k, j), where a(i, k) and b(k, j) read A and B, each
/// optionally transposed.
template <bool kTransposeA, bool kTransposeB>
void accumulate(vnl_matrix<double>& X, const vnl_matrix<double>& A, const vnl_matrix<double>& B, double sign) {
  const std::size_t rows = kTransposeA ? A.cols() : A.rows();
  const std::size_t inner = kTransposeA ? A.rows() : A.cols();
  const std::size_t cols = kTransposeB ? B.rows() : B.cols();
  assert((kTransposeB ? B.cols() : B.rows()) == inner);
  assert(X.rows() == rows && X.cols() == cols);
  for (std::size_t i = 0; i < rows; ++i) {
    for (std::size_t j = 0; j < cols; ++j) {
      double total = 0;
      for (std::size_t k = 0; k < inner; ++k) {
        total += (kTransposeA ? A(k, i) : A(i, k)) * (kTransposeB ? B(j, k) : B(k, j));
      }
      X(i, j) += sign * total;
    }
  }
}

template <bool kTransposeA, bool kTransposeB>
void assign(vnl_matrix<double>& out, const vnl_matrix<double>& A, const vnl_matrix<double>& B) {
  const std::size_t rows = kTransposeA ? A.cols() : A.rows();
  const std::size_t cols = kTransposeB ? B.rows() : B.cols();
  if (out.rows() != rows || out.cols() != cols) {
    out.set_size(rows, cols);
  } else {
    out.fill(0.0);
  }
  accumulate<kTransposeA, kTransposeB>(out, A, B, 1.0);
}

/// X += sign * A^T b.
void accumulate_atb(vnl_vector<double>& X, const vnl_matrix<double>& A, const vnl_vector<double>& b, double sign) {
  assert(A.rows() == b.size() && X.size() == A.cols());
  for (std::size_t j = 0; j < A.cols(); ++j) {
    double total = 0;
    for (std::size_t i = 0; i < A.rows(); ++i) total += A(i, j) * b[i];
    X[j] += sign * total;
  }
}
}  // namespace

void vnl_fastops::AtA(vnl_matrix<double>& out, const vnl_matrix<double>& A) { assign<true, false>(out, A, A); }
void vnl_fastops::AB(vnl_matrix<double>& out, const vnl_matrix<double>& A, const vnl_matrix<double>& B) {
  assign<false, false>(out, A, B);
}
void vnl_fastops::AtB(vnl_matrix<double>& out, const vnl_matrix<double>& A, const vnl_matrix<double>& B) {
  assign<true, false>(out, A, B);
}
void vnl_fastops::AtB(vnl_vector<double>& out, const vnl_matrix<double>& A, const vnl_vector<double>& b) {
  out.set_size(A.cols());
  accumulate_atb(out, A, b, 1.0);
}
void vnl_fastops::Ab(vnl_vector<double>& out, const vnl_matrix<double>& A, const vnl_vector<double>& b) {
  out = A * b;
}
void vnl_fastops::ABt(vnl_matrix<double>& out, const vnl_matrix<double>& A, const vnl_matrix<double>& B) {
  assign<false, true>(out, A, B);
}
double vnl_fastops::btAb(const vnl_matrix<double>& A, const vnl_vector<double>& b) {
  assert(A.rows() == b.size() && A.cols() == b.size());
  return dot_product(b, A * b);
}
void vnl_fastops::ABAt(vnl_matrix<double>& out, const vnl_matrix<double>& A, const vnl_matrix<double>& B) {
  vnl_matrix<double> ab;
  AB(ab, A, B);
  ABt(out, ab, A);
}

void vnl_fastops::inc_X_by_AtA(vnl_matrix<double>& X, const vnl_matrix<double>& A) {
  accumulate<true, false>(X, A, A, 1.0);
}
void vnl_fastops::inc_X_by_AB(vnl_matrix<double>& X, const vnl_matrix<double>& A, const vnl_matrix<double>& B) {
  accumulate<false, false>(X, A, B, 1.0);
}
void vnl_fastops::inc_X_by_AtB(vnl_matrix<double>& X, const vnl_matrix<double>& A, const vnl_matrix<double>& B) {
  accumulate<true, false>(X, A, B, 1.0);
}
void vnl_fastops::inc_X_by_AtB(vnl_vector<double>& X, const vnl_matrix<double>& A, const vnl_vector<double>& b) {
  accumulate_atb(X, A, b, 1.0);
}
void vnl_fastops::inc_X_by_ABt(vnl_matrix<double>& X, const vnl_matrix<double>& A, const vnl_matrix<double>& B) {
  accumulate<false, true>(X, A, B, 1.0);
}
void vnl_fastops::inc_X_by_ABAt(vnl_matrix<double>& X, const vnl_matrix<double>& A, const vnl_matrix<double>& B) {
  vnl_matrix<double> ab;
  AB(ab, A, B);
  accumulate<false, true>(X, ab, A, 1.0);
}

void vnl_fastops::dec_X_by_AtA(vnl_matrix<double>& X, const vnl_matrix<double>& A) {
  accumulate<true, false>(X, A, A, -1.0);
}
void vnl_fastops::dec_X_by_AB(vnl_matrix<double>& X, const vnl_matrix<double>& A, const vnl_matrix<double>& B) {
  accumulate<false, false>(X, A, B, -1.0);
}
void vnl_fastops::dec_X_by_AtB(vnl_matrix<double>& X, const vnl_matrix<double>& A, const vnl_matrix<double>& B) {
  accumulate<true, false>(X, A, B, -1.0);
}
void vnl_fastops::dec_X_by_AtB(vnl_vector<double>& X, const vnl_matrix<double>& A, const vnl_vector<double>& b) {
  accumulate_atb(X, A, b, -1.0);
}
void vnl_fastops::dec_X_by_ABt(vnl_matrix<double>& X, const vnl_matrix<double>& A, const vnl_matrix<double>& B) {
  accumulate<false, true>(X, A, B, -1.0);
}

double vnl_fastops::dot(const double* a, const double* b, unsigned int n) {
  double total = 0;
  for (unsigned i = 0; i < n; ++i) total += a[i] * b[i];
  return total;
}

}  // inline namespace edgetrack_ports
