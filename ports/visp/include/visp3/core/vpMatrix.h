// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors ViSP's visp3/core/vpMatrix.h: a dense row-major matrix of `real` (upstream: double),
/// the subset the moving edges use: products, transpose, identity, insert, and the SVD with its
/// pseudo-inverse and null space. The SVD is our own one-sided Jacobi (Hestenes) on `real`, not a
/// library call: singular values come sorted in decreasing order, as upstream's; the sign of each
/// singular vector is fixed so that its largest component is positive (upstream's is whatever its
/// SVD library gives: GSL in Debian's build).
#pragma once

#ifdef vpMatrix_H
#error "edgetrack's drop-in visp3/core/vpMatrix.h and ViSP's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cstddef>
#include <vector>

#include "real/real.h"
#include "visp3/core/vpColVector.h"

inline namespace edgetrack_ports {

class vpMatrix {
 public:
  vpMatrix() = default;
  vpMatrix(unsigned int rows, unsigned int cols) : rows_(rows), cols_(cols), data_(std::size_t{rows} * cols, real(0)) {}
  vpMatrix(unsigned int rows, unsigned int cols, real value)
      : rows_(rows), cols_(cols), data_(std::size_t{rows} * cols, value) {}

  unsigned int getRows() const { return rows_; }
  unsigned int getCols() const { return cols_; }
  unsigned int size() const { return rows_ * cols_; }
  /// New size; zero elements when flagNullify is true (upstream's default), else unspecified
  /// values for the new ones (the old storage reused row-major, as upstream).
  void resize(unsigned int rows, unsigned int cols, bool flagNullify = true);

  real* operator[](unsigned int r) { return data_.data() + std::size_t{r} * cols_; }
  const real* operator[](unsigned int r) const { return data_.data() + std::size_t{r} * cols_; }

  vpMatrix& operator=(real value);
  /// The identity of the current size (the diagonal of a rectangular one).
  void eye();
  void eye(unsigned int n);
  void eye(unsigned int rows, unsigned int cols);
  vpMatrix t() const;
  vpMatrix transpose() const { return t(); }
  /// Copies A into this matrix with A's (0, 0) at (r, c); A must fit.
  void insert(const vpMatrix& A, unsigned int r, unsigned int c);
  vpColVector getCol(unsigned int j) const;

  vpMatrix operator*(const vpMatrix& B) const;
  vpColVector operator*(const vpColVector& v) const;
  vpMatrix operator+(const vpMatrix& B) const;
  vpMatrix operator-(const vpMatrix& B) const;
  vpMatrix operator*(real s) const;
  vpMatrix& operator*=(real s);

  real frobeniusNorm() const;
  real sumSquare() const;

  /// Singular value decomposition A = U diag(w) V^T with this matrix (rows >= cols) replaced by
  /// U, as upstream's svd(); w in decreasing order.
  void svd(vpColVector& w, vpMatrix& V);
  /// Moore-Penrose pseudo-inverse; singular values at or below svThreshold times the largest
  /// count as zero.
  vpMatrix pseudoInverse(real svThreshold = real(1e-6)) const;
  /// The `dim` right singular vectors of the smallest singular values, as columns of kerA;
  /// returns the number of singular values at or below 1e-6 times the largest (upstream's rule).
  unsigned int nullSpace(vpMatrix& kerA, int dim) const;
#if defined(EDGETRACK_REAL_S47_16) || defined(EDGETRACK_REAL_S40_23)
  vpMatrix pseudoInverse(double svThreshold) const { return pseudoInverse(real(svThreshold)); }
#endif

 private:
  unsigned int rows_ = 0, cols_ = 0;
  std::vector<real> data_;
};

inline vpMatrix operator*(real s, const vpMatrix& A) { return A * s; }

}  // inline namespace edgetrack_ports
