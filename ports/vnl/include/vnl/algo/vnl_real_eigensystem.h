// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_real_eigensystem.h: eigenvalues and eigenvectors of a real,
/// not necessarily symmetric, square matrix (prefer vnl_symmetric_eigensystem for a symmetric
/// one). Ours: Householder reduction to Hessenberg form and Francis double-shift QR for the
/// eigenvalues, then inverse iteration in complex arithmetic for each eigenvector, normalised to
/// unit length (upstream: EISPACK rg). As upstream, Vreal holds a real eigenvector per real
/// eigenvalue and, for a complex pair, the real and imaginary parts of the first one's
/// eigenvector in two columns; V holds the complex eigenvectors, D the eigenvalues (pairs
/// adjacent, first the one with positive imaginary part). A repeated eigenvalue gets the same
/// eigenvector for each copy.
#pragma once

#ifdef vnl_real_eigensystem_h_
#error "edgetrack's drop-in vnl/algo/vnl_real_eigensystem.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <complex>

#include "vnl/vnl_diag_matrix.h"
#include "vnl/vnl_matrix.h"

inline namespace edgetrack_ports {

class vnl_real_eigensystem {
 public:
  explicit vnl_real_eigensystem(const vnl_matrix<double>& M);

  vnl_matrix<double> Vreal;
  vnl_matrix<std::complex<double>> V;
  vnl_diag_matrix<std::complex<double>> D;
};

}  // inline namespace edgetrack_ports
