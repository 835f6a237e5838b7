// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_inverse.h: closed-form inverses of 1x1 to 4x4 matrices (the
/// adjugate over the determinant), and vnl_inverse_transpose. A singular matrix gives the zero
/// matrix, as upstream. Larger matrices go through vnl_matrix_inverse (vnl/algo).
#pragma once

#ifdef vnl_inverse_h_
#error "edgetrack's drop-in vnl/vnl_inverse.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cassert>

#include "vnl/vnl_det.h"
#include "vnl/vnl_matrix.h"
#include "vnl/vnl_matrix_fixed.h"

inline namespace edgetrack_ports {

namespace vnl_inverse_detail {
/// The adjugate of the n x n row-major block a (n <= 4), written to out.
template <class T>
void adjugate(const T* a, unsigned n, T* out) {
  if (n == 1) {
    out[0] = T(1);
    return;
  }
  for (unsigned r = 0; r < n; ++r) {
    for (unsigned c = 0; c < n; ++c) {
      T minor[9];
      unsigned k = 0;
      for (unsigned i = 0; i < n; ++i) {
        for (unsigned j = 0; j < n; ++j) {
          if (i != r && j != c) minor[k++] = a[i * n + j];
        }
      }
      const unsigned m = n - 1;
      T det;
      if (m == 1) {
        det = minor[0];
      } else if (m == 2) {
        det = vnl_det(minor, minor + 2);
      } else {
        det = vnl_det(minor, minor + 3, minor + 6);
      }
      out[c * n + r] = (r + c) % 2 == 0 ? det : -det;  // transposed cofactor
    }
  }
}
template <class T>
T determinant(const T* a, unsigned n) {
  switch (n) {
    case 1:
      return a[0];
    case 2:
      return vnl_det(a, a + 2);
    case 3:
      return vnl_det(a, a + 3, a + 6);
    default:
      return vnl_det(a, a + 4, a + 8, a + 12);
  }
}
template <class T>
void inverse(const T* a, unsigned n, T* out) {
  const T det = determinant(a, n);
  for (unsigned i = 0; i < n * n; ++i) out[i] = T(0);
  if (det == T(0)) return;
  adjugate(a, n, out);
  for (unsigned i = 0; i < n * n; ++i) out[i] /= det;
}
}  // namespace vnl_inverse_detail

template <class T, unsigned n>
vnl_matrix_fixed<T, n, n> vnl_inverse(const vnl_matrix_fixed<T, n, n>& m) {
  static_assert(n >= 1 && n <= 4, "vnl_inverse: 1x1 to 4x4 only; use vnl_matrix_inverse");
  vnl_matrix_fixed<T, n, n> result;
  vnl_inverse_detail::inverse(m.data_block(), n, result.data_block());
  return result;
}

/// The inverse of a square matrix of at most 4 rows (asserts otherwise).
template <class T>
vnl_matrix<T> vnl_inverse(const vnl_matrix<T>& m) {
  assert(m.rows() == m.cols() && m.rows() >= 1 && m.rows() <= 4);
  vnl_matrix<T> result(m.rows(), m.cols());
  vnl_inverse_detail::inverse(m.data_block(), static_cast<unsigned>(m.rows()), result.data_block());
  return result;
}

template <class T, unsigned n>
vnl_matrix_fixed<T, n, n> vnl_inverse_transpose(const vnl_matrix_fixed<T, n, n>& m) {
  return vnl_inverse(m).transpose();
}

template <class T>
vnl_matrix<T> vnl_inverse_transpose(const vnl_matrix<T>& m) {
  return vnl_inverse(m).transpose();
}

}  // inline namespace edgetrack_ports
