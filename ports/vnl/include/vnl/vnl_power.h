// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_power.h: M^n by repeated squaring; a negative n (matrices up to
/// 4x4, as upstream) inverts with vnl_inverse first.
#pragma once

#ifdef vnl_power_h_
#error "edgetrack's drop-in vnl/vnl_power.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cassert>

#include "vnl/vnl_inverse.h"
#include "vnl/vnl_matrix.h"
#include "vnl/vnl_matrix_fixed.h"

inline namespace edgetrack_ports {

template <class T, unsigned int d>
vnl_matrix_fixed<T, d, d> vnl_power(const vnl_matrix_fixed<T, d, d>& m, int n) {
  if (n == 0) return vnl_matrix_fixed<T, d, d>().set_identity();
  if (n < 0) {
    if constexpr (d <= 4) {
      return vnl_power(vnl_inverse(m), -n);
    } else {
      assert(!"vnl_power: negative powers need d <= 4");
      return m;
    }
  }
  const vnl_matrix_fixed<T, d, d> half = vnl_power(m, n / 2);
  return n % 2 == 0 ? half * half : half * half * m;
}

template <class T>
vnl_matrix<T> vnl_power(const vnl_matrix<T>& m, int n) {
  assert(m.rows() == m.cols());
  if (n == 0) return vnl_matrix<T>(m.rows(), m.cols(), vnl_matrix_identity);
  if (n < 0) return vnl_power(vnl_inverse(m), -n);
  const vnl_matrix<T> half = vnl_power(m, n / 2);
  return n % 2 == 0 ? half * half : half * half * m;
}

}  // inline namespace edgetrack_ports
