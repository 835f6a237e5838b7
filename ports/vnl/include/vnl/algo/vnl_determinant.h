// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_determinant.h: the determinant of any square matrix, in
/// closed form up to 4x4 (vnl_det) and by QR beyond, as upstream does. `balance` (upstream:
/// scale rows and columns to unit norm first, for range) is honoured the same way.
#pragma once

#ifdef vnl_algo_determinant_h_
#error "edgetrack's drop-in vnl/algo/vnl_determinant.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cassert>
#include <cmath>

#include "vnl/algo/vnl_qr.h"
#include "vnl/vnl_det.h"
#include "vnl/vnl_matrix.h"
#include "vnl/vnl_matrix_fixed.h"

inline namespace edgetrack_ports {

template <class T>
T vnl_determinant(const T* row0, const T* row1) {
  return vnl_det(row0, row1);
}
template <class T>
T vnl_determinant(const T* row0, const T* row1, const T* row2) {
  return vnl_det(row0, row1, row2);
}
template <class T>
T vnl_determinant(const T* row0, const T* row1, const T* row2, const T* row3) {
  return vnl_det(row0, row1, row2, row3);
}

template <class T>
T vnl_determinant(const vnl_matrix<T>& M, bool balance = false) {
  using std::sqrt;
  assert(M.rows() == M.cols());
  const std::size_t n = M.rows();
  if (n <= 4 && !balance) return vnl_det(M);
  if (!balance) return vnl_qr<T>(M).determinant();
  // Scale each row, then each column, to unit two-norm; the scales multiply back in.
  vnl_matrix<T> m(M);
  T scale(1);
  for (std::size_t r = 0; r < n; ++r) {
    const T norm = m.get_row(r).two_norm();
    if (norm == T(0)) return T(0);
    m.scale_row(r, T(1) / norm);
    scale *= norm;
  }
  for (std::size_t c = 0; c < n; ++c) {
    const T norm = m.get_column(c).two_norm();
    if (norm == T(0)) return T(0);
    m.scale_column(c, T(1) / norm);
    scale *= norm;
  }
  return scale * vnl_qr<T>(m).determinant();
}

/// Integer matrices: the determinant computed in double and rounded (as upstream).
inline int vnl_determinant(const vnl_matrix<int>& M, bool balance = false) {
  vnl_matrix<double> m(M.rows(), M.cols());
  for (std::size_t i = 0; i < M.size(); ++i) m.data_block()[i] = M.data_block()[i];
  const double det = vnl_determinant(m, balance);
  return static_cast<int>(det < 0 ? det - 0.5 : det + 0.5);
}

template <class T, unsigned m, unsigned n>
T vnl_determinant(const vnl_matrix_fixed<T, m, n>& M, bool balance = false) {
  return vnl_determinant(M.as_matrix(), balance);
}

}  // inline namespace edgetrack_ports
