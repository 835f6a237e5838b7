// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_sparse_symmetric_eigensystem.h: some eigenpairs of a
/// symmetric sparse matrix A (A x = lambda x), or of A x = lambda B x with B positive definite.
/// Ours solves the problem densely (vnl_symmetric_eigensystem, vnl_generalized_eigensystem) and
/// keeps the pairs asked for, so it suits matrices of up to a few hundred unknowns (upstream:
/// Lanczos iteration and ARPACK, for large ones); tolerance, the Lanczos vector count and the
/// iteration limit have nothing to tune here. Pairs come smallest first when `smallest`, else
/// largest first, by value or (magnitude) by |lambda - sigma|. CalculateNPairs returns 0 on
/// success, non-zero for bad input (too many pairs, sizes that differ, B not positive definite).
#pragma once

#ifdef vnl_sparse_symmetric_eigensystem_h_
#error "edgetrack's drop-in vnl/algo/vnl_sparse_symmetric_eigensystem.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <vector>

#include "vnl/vnl_sparse_matrix.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

class vnl_sparse_symmetric_eigensystem {
 public:
  vnl_sparse_symmetric_eigensystem() = default;

  int CalculateNPairs(vnl_sparse_matrix<double>& M, int n, bool smallest = true, long nfigures = 10);
  int CalculateNPairs(vnl_sparse_matrix<double>& A, vnl_sparse_matrix<double>& B, int nEV, double tolerance = 0,
                      int numberLanczosVecs = 0, bool smallest = false, bool magnitude = true, int maxIterations = 0,
                      double sigma = 0.0);
  vnl_vector<double> get_eigenvector(int i) const { return vectors[static_cast<size_t>(i)]; }
  double get_eigenvalue(int i) const { return values[static_cast<size_t>(i)]; }

  /// q = A p for m vectors of length n (upstream's Lanczos callback); 0 on success.
  int CalculateProduct(int n, int m, const double* p, double* q);
  /// Keep and give back m vectors of length n under the index `base` (upstream's callbacks).
  int SaveVectors(int n, int m, const double* q, int base);
  int RestoreVectors(int n, int m, double* q, int base);

 protected:
  int nvalues = 0;
  std::vector<vnl_vector<double>> vectors;
  std::vector<double> values;
  vnl_sparse_matrix<double>* mat = nullptr;
  vnl_sparse_matrix<double>* Bmat = nullptr;
  std::vector<std::vector<double>> temp_store;

 private:
  /// Keeps nEV of the eigenpairs (columns of V, values D) by the selection rules above.
  void keep(const vnl_matrix<double>& V, const vnl_vector<double>& D, int nEV, bool smallest, bool magnitude,
            double sigma);
};

}  // inline namespace edgetrack_ports
