// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_complex_eigensystem.h: the eigenvalues W of a square complex
/// matrix A and, on request, its right (A r = w r) and left (l A = w l) eigenvectors, stored as
/// the rows of R and L, each of unit length. Ours: Householder reduction to Hessenberg form,
/// shifted QR with Wilkinson shifts and Givens rotations for the eigenvalues, inverse iteration
/// for the vectors (upstream: LAPACK zgeev). The order of the eigenvalues is not upstream's.
#pragma once

#ifdef vnl_complex_eigensystem_h_
#error "edgetrack's drop-in vnl/algo/vnl_complex_eigensystem.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <complex>

#include "vnl/vnl_matrix.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

class vnl_complex_eigensystem {
 public:
  const unsigned int N;
  vnl_matrix<std::complex<double>> L;  ///< left eigenvectors, as rows
  vnl_matrix<std::complex<double>> R;  ///< right eigenvectors, as rows
  vnl_vector<std::complex<double>> W;  ///< eigenvalues

  vnl_complex_eigensystem(const vnl_matrix<double>& A_real, const vnl_matrix<double>& A_imag, bool right = true,
                          bool left = false);
  vnl_complex_eigensystem(const vnl_matrix<std::complex<double>>& A, bool right = true, bool left = false);

  std::complex<double> eigen_value(unsigned i) const { return W[i]; }
  vnl_vector<std::complex<double>> left_eigen_vector(unsigned i) const { return L.get_row(i); }
  vnl_vector<std::complex<double>> right_eigen_vector(unsigned i) const { return R.get_row(i); }

 private:
  void compute(const vnl_matrix<std::complex<double>>& A, bool right, bool left);
};

}  // inline namespace edgetrack_ports
