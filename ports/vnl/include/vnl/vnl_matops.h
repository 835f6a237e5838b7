// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_matops.h: double matrix concatenation, the distance between
/// matrices up to scale, and float/double conversion of whole containers.
#pragma once

#ifdef vnl_matops_h_
#error "edgetrack's drop-in vnl/vnl_matops.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_matrix.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

class vnl_matops {
 public:
  /// |A/|A| - B/|B|| in the Frobenius norm, choosing the sign of B that makes it smallest.
  static double homg_diff(const vnl_matrix<double>& A, const vnl_matrix<double>& B);
  /// [A B] side by side (same number of rows); a vector counts as one column.
  static vnl_matrix<double> cat(const vnl_matrix<double>& A, const vnl_matrix<double>& B);
  static vnl_matrix<double> cat(const vnl_matrix<double>& A, const vnl_vector<double>& B);
  static vnl_matrix<double> cat(const vnl_vector<double>& A, const vnl_matrix<double>& B);
  /// [A; B] stacked (same number of columns).
  static vnl_matrix<double> vcat(const vnl_matrix<double>& A, const vnl_matrix<double>& B);
  static vnl_matrix<double> f2d(const vnl_matrix<float>&);
  static vnl_vector<double> f2d(const vnl_vector<float>&);
  static vnl_matrix<float> d2f(const vnl_matrix<double>&);
  static vnl_vector<float> d2f(const vnl_vector<double>&);
};

}  // inline namespace edgetrack_ports
