// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_det.h: closed-form determinants of 1x1 to 4x4 matrices, from
/// row pointers or from a matrix. Larger matrices go through vnl_determinant (vnl/algo).
#pragma once

#ifdef vnl_det_h_
#error "edgetrack's drop-in vnl/vnl_det.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cassert>

#include "vnl/vnl_matrix.h"
#include "vnl/vnl_matrix_fixed.h"

inline namespace edgetrack_ports {

template <class T>
T vnl_det(const T* row0, const T* row1) {
  return row0[0] * row1[1] - row0[1] * row1[0];
}

template <class T>
T vnl_det(const T* row0, const T* row1, const T* row2) {
  return row0[0] * (row1[1] * row2[2] - row1[2] * row2[1]) - row0[1] * (row1[0] * row2[2] - row1[2] * row2[0]) +
         row0[2] * (row1[0] * row2[1] - row1[1] * row2[0]);
}

template <class T>
T vnl_det(const T* row0, const T* row1, const T* row2, const T* row3) {
  // Laplace expansion along the first row, each minor by the 3x3 rule.
  const T* rows[4] = {row0, row1, row2, row3};
  T total(0);
  for (int skip = 0; skip < 4; ++skip) {
    T minor_rows[3][3];
    for (int r = 1; r < 4; ++r) {
      int k = 0;
      for (int c = 0; c < 4; ++c) {
        if (c != skip) minor_rows[r - 1][k++] = rows[r][c];
      }
    }
    const T minor = vnl_det(minor_rows[0], minor_rows[1], minor_rows[2]);
    total += (skip % 2 == 0 ? rows[0][skip] : -rows[0][skip]) * minor;
  }
  return total;
}

template <class T>
T vnl_det(const vnl_matrix_fixed<T, 1, 1>& m) {
  return m(0, 0);
}
template <class T>
T vnl_det(const vnl_matrix_fixed<T, 2, 2>& m) {
  return vnl_det(m[0], m[1]);
}
template <class T>
T vnl_det(const vnl_matrix_fixed<T, 3, 3>& m) {
  return vnl_det(m[0], m[1], m[2]);
}
template <class T>
T vnl_det(const vnl_matrix_fixed<T, 4, 4>& m) {
  return vnl_det(m[0], m[1], m[2], m[3]);
}

/// The determinant of a square matrix of at most 4 rows (asserts otherwise).
template <class T>
T vnl_det(const vnl_matrix<T>& m) {
  assert(m.rows() == m.cols());
  switch (m.rows()) {
    case 0:
      return T(1);
    case 1:
      return m(0, 0);
    case 2:
      return vnl_det(m[0], m[1]);
    case 3:
      return vnl_det(m[0], m[1], m[2]);
    case 4:
      return vnl_det(m[0], m[1], m[2], m[3]);
    default:
      assert(!"vnl_det: larger than 4x4; use vnl_determinant");
      return T(0);
  }
}

}  // inline namespace edgetrack_ports
