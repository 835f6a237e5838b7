// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_scatter_3x3.h: a 3 x 3 scatter matrix, the sum of outer
/// products v v^T (or v u^T, after which it counts as asymmetric until force_symmetric), with its
/// eigensystem (vnl_symmetric_eigensystem: ascending eigenvalues, eigenvectors as columns of V)
/// computed on demand. As upstream, an asymmetric scatter gets no eigensystem (a warning).
#pragma once

#ifdef vnl_scatter_3x3_h_
#error "edgetrack's drop-in vnl/algo/vnl_scatter_3x3.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_matrix_fixed.h"
#include "vnl/vnl_vector_fixed.h"

inline namespace edgetrack_ports {

template <class T>
class vnl_scatter_3x3 : public vnl_matrix_fixed<T, 3, 3> {
 public:
  using base = vnl_matrix_fixed<T, 3, 3>;
  using vect = vnl_vector_fixed<T, 3>;

  vnl_scatter_3x3() : base(T(0)) {}

  /// Adds v v^T (stays symmetric).
  void add_outer_product(const vnl_vector_fixed<T, 3>& v);
  /// Adds v u^T (element (i, j) += v[i] u[j]).
  void add_outer_product(const vnl_vector_fixed<T, 3>& u, const vnl_vector_fixed<T, 3>& v);
  void sub_outer_product(const vnl_vector_fixed<T, 3>& v);
  void sub_outer_product(const vnl_vector_fixed<T, 3>& u, const vnl_vector_fixed<T, 3>& v);
  /// Replaces S by (S + S^T) / 2.
  void force_symmetric();
  void compute_eigensystem();
  /// The eigenvector of the smallest eigenvalue.
  vnl_vector_fixed<T, 3> minimum_eigenvector() {
    if (!eigenvectors_currentp) compute_eigensystem();
    return vnl_vector_fixed<T, 3>(V_(0, 0), V_(1, 0), V_(2, 0));
  }
  vnl_matrix_fixed<T, 3, 3>& V() {
    if (!eigenvectors_currentp) compute_eigensystem();
    return V_;
  }

 protected:
  bool symmetricp = true;
  bool eigenvectors_currentp = false;
  vnl_matrix_fixed<T, 3, 3> V_;
  vnl_vector_fixed<T, 3> D;
};

}  // inline namespace edgetrack_ports
