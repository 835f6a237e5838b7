// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_qr.h: M = Q R for an m x n matrix, Q (m x m) orthogonal and
/// R (m x n) upper trapezoidal; solve, determinant, inverse. Upstream calls LINPACK's dqrdc
/// (Householder reflections, no pivoting); ours is our own Householder QR written on T, the
/// same method, so Q and R agree with upstream's to rounding, up to the sign of each
/// reflection (a row of R and the matching column of Q may both change sign).
#pragma once

#ifdef vnl_qr_h_
#error "edgetrack's drop-in vnl/algo/vnl_qr.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_matrix.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

template <class T>
class vnl_qr {
 public:
  explicit vnl_qr(const vnl_matrix<T>& M);

  vnl_matrix<T> inverse() const;
  /// The inverse of M^T.
  vnl_matrix<T> tinverse() const { return inverse().transpose(); }
  /// Q R, which is M to rounding.
  vnl_matrix<T> recompose() const { return Q() * R(); }
  /// The least-squares X with M X = rhs (square or tall M of full column rank).
  vnl_matrix<T> solve(const vnl_matrix<T>& rhs) const;
  vnl_vector<T> solve(const vnl_vector<T>& rhs) const;
  /// det M for square M: the product of R's diagonal times det Q (+-1).
  T determinant() const;
  const vnl_matrix<T>& Q() const { return Q_; }
  const vnl_matrix<T>& R() const { return R_; }
  /// Q^T b.
  vnl_vector<T> QtB(const vnl_vector<T>& b) const { return Q_.transpose() * b; }
  void extract_q_and_r(vnl_matrix<T>* q, vnl_matrix<T>* r) const {
    *q = Q_;
    *r = R_;
  }

 private:
  vnl_matrix<T> Q_;
  vnl_matrix<T> R_;
  int reflections_ = 0;  // each applied Householder reflection has determinant -1
};

/// det M by QR (upstream's vnl_qr_determinant).
template <class T>
T vnl_qr_determinant(const vnl_matrix<T>& m) {
  return vnl_qr<T>(m).determinant();
}

}  // inline namespace edgetrack_ports
