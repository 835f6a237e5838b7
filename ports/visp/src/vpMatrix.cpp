// SPDX-License-Identifier: BSD-3-Clause
/// vpMatrix: products and the SVD by one-sided Jacobi rotations (Hestenes): the columns of
/// U = A V are made pairwise orthogonal by plane rotations accumulated in V; the singular values
/// are then U's column norms. It works on `real` as it is (no square of A's condition number,
/// which fixed point could not afford), converging quadratically; at most kMaxSweeps sweeps.
#include "visp3/core/vpMatrix.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

inline namespace edgetrack_ports {

namespace {

constexpr int kMaxSweeps = 40;

/// A pair of columns counts as orthogonal when |<p, q>| <= tolerance * |p| |q| + noise floor.
real orthogonality_tolerance() {
  const real eps = std::numeric_limits<real>::epsilon();
  return eps * 4;
}

/// The absolute size below which a fixed-point dot product of `terms` products is rounding
/// noise (each product rounds to an ulp); without it a pair whose |p| |q| is small never passes
/// the relative test and every sweep rotates noise into U and V. Zero for floating point, which
/// rounds relatively.
real dot_product_noise_floor(unsigned int terms) {
  if constexpr (std::numeric_limits<real>::is_iec559) {
    return real(0);
  } else {
    return std::numeric_limits<real>::epsilon() * real(static_cast<int>(terms) + 1);
  }
}

struct Rotation {
  real c, s;
};

/// The rotation that makes columns with squared norms alpha, beta and product gamma orthogonal.
Rotation jacobi_rotation(real alpha, real beta, real gamma) {
  using std::abs;
  using std::sqrt;
  const real zeta = (beta - alpha) / (gamma * 2);
  const real abs_zeta = abs(zeta);
  // t = sign(zeta) / (|zeta| + sqrt(1 + zeta^2)), written so that zeta^2 cannot overflow.
  const real root = abs_zeta > 1 ? abs_zeta * sqrt(real(1) + (real(1) / abs_zeta) / abs_zeta) : sqrt(real(1) + zeta * zeta);
  real t = real(1) / (abs_zeta + root);
  if (zeta < 0) t = -t;
  const real c = real(1) / sqrt(real(1) + t * t);
  return {c, c * t};
}

void rotate_columns(vpMatrix& M, unsigned int p, unsigned int q, Rotation r) {
  for (unsigned int k = 0; k < M.getRows(); ++k) {
    const real a = M[k][p], b = M[k][q];
    M[k][p] = r.c * a - r.s * b;
    M[k][q] = r.s * a + r.c * b;
  }
}

/// Orthogonalises U's columns in place and accumulates the rotations in V (starts as identity).
void hestenes(vpMatrix& U, vpMatrix& V) {
  using std::abs;
  using std::sqrt;
  const unsigned int m = U.getRows(), n = U.getCols();
  const real tolerance = orthogonality_tolerance();
  const real noise = dot_product_noise_floor(m);
  for (int sweep = 0; sweep < kMaxSweeps; ++sweep) {
    bool rotated = false;
    for (unsigned int p = 0; p + 1 < n; ++p) {
      for (unsigned int q = p + 1; q < n; ++q) {
        real alpha = 0, beta = 0, gamma = 0;
        for (unsigned int k = 0; k < m; ++k) {
          alpha += U[k][p] * U[k][p];
          beta += U[k][q] * U[k][q];
          gamma += U[k][p] * U[k][q];
        }
        if (abs(gamma) <= tolerance * sqrt(alpha) * sqrt(beta) + noise) continue;
        const Rotation r = jacobi_rotation(alpha, beta, gamma);
        rotate_columns(U, p, q, r);
        rotate_columns(V, p, q, r);
        rotated = true;
      }
    }
    if (!rotated) break;
  }
}

}  // namespace

void vpMatrix::resize(unsigned int rows, unsigned int cols, bool flagNullify) {
  rows_ = rows;
  cols_ = cols;
  if (flagNullify) {
    data_.assign(std::size_t{rows} * cols, real(0));
  } else {
    data_.resize(std::size_t{rows} * cols, real(0));
  }
}

vpMatrix& vpMatrix::operator=(real value) {
  std::fill(data_.begin(), data_.end(), value);
  return *this;
}

void vpMatrix::eye() {
  *this = real(0);
  for (unsigned int k = 0; k < rows_ && k < cols_; ++k) (*this)[k][k] = 1;
}

void vpMatrix::eye(unsigned int n) { eye(n, n); }

void vpMatrix::eye(unsigned int rows, unsigned int cols) {
  resize(rows, cols);
  eye();
}

vpMatrix vpMatrix::t() const {
  vpMatrix T(cols_, rows_);
  for (unsigned int r = 0; r < rows_; ++r)
    for (unsigned int c = 0; c < cols_; ++c) T[c][r] = (*this)[r][c];
  return T;
}

void vpMatrix::insert(const vpMatrix& A, unsigned int r, unsigned int c) {
  for (unsigned int a = 0; a < A.getRows() && r + a < rows_; ++a)
    for (unsigned int b = 0; b < A.getCols() && c + b < cols_; ++b) (*this)[r + a][c + b] = A[a][b];
}

vpColVector vpMatrix::getCol(unsigned int j) const {
  vpColVector v(rows_);
  for (unsigned int r = 0; r < rows_; ++r) v[r] = (*this)[r][j];
  return v;
}

vpMatrix vpMatrix::operator*(const vpMatrix& B) const {
  vpMatrix C(rows_, B.cols_);
  for (unsigned int r = 0; r < rows_; ++r)
    for (unsigned int k = 0; k < cols_; ++k) {
      const real a = (*this)[r][k];
      for (unsigned int c = 0; c < B.cols_; ++c) C[r][c] += a * B[k][c];
    }
  return C;
}

vpColVector vpMatrix::operator*(const vpColVector& v) const {
  vpColVector w(rows_);
  for (unsigned int r = 0; r < rows_; ++r) {
    real s = 0;
    for (unsigned int c = 0; c < cols_; ++c) s += (*this)[r][c] * v[c];
    w[r] = s;
  }
  return w;
}

vpMatrix vpMatrix::operator+(const vpMatrix& B) const {
  vpMatrix C(*this);
  for (std::size_t k = 0; k < data_.size(); ++k) C.data_[k] += B.data_[k];
  return C;
}

vpMatrix vpMatrix::operator-(const vpMatrix& B) const {
  vpMatrix C(*this);
  for (std::size_t k = 0; k < data_.size(); ++k) C.data_[k] -= B.data_[k];
  return C;
}

vpMatrix vpMatrix::operator*(real s) const {
  vpMatrix C(*this);
  return C *= s;
}

vpMatrix& vpMatrix::operator*=(real s) {
  for (real& x : data_) x *= s;
  return *this;
}

real vpMatrix::sumSquare() const {
  real s = 0;
  for (const real& x : data_) s += x * x;
  return s;
}

real vpMatrix::frobeniusNorm() const {
  using std::sqrt;
  return sqrt(sumSquare());
}

void vpMatrix::svd(vpColVector& w, vpMatrix& V) {
  using std::abs;
  using std::sqrt;
  const unsigned int m = rows_, n = cols_;
  vpMatrix Vr;
  Vr.eye(n);
  hestenes(*this, Vr);

  vpColVector norms(n);
  for (unsigned int c = 0; c < n; ++c) {
    real s = 0;
    for (unsigned int k = 0; k < m; ++k) s += (*this)[k][c] * (*this)[k][c];
    norms[c] = sqrt(s);
  }
  std::vector<unsigned int> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](unsigned int a, unsigned int b) { return norms[a] > norms[b]; });

  const vpMatrix Ur(*this);
  w.resize(n);
  V.resize(n, n);
  for (unsigned int c = 0; c < n; ++c) {
    const unsigned int from = order[c];
    // Sign: the largest component of the right singular vector is positive.
    unsigned int largest = 0;
    for (unsigned int k = 1; k < n; ++k)
      if (abs(Vr[k][from]) > abs(Vr[largest][from])) largest = k;
    const real sign = Vr[largest][from] < 0 ? real(-1) : real(1);
    w[c] = norms[from];
    for (unsigned int k = 0; k < n; ++k) V[k][c] = sign * Vr[k][from];
    for (unsigned int k = 0; k < m; ++k)
      (*this)[k][c] = norms[from] > 0 ? sign * Ur[k][from] / norms[from] : real(0);
  }
}

vpMatrix vpMatrix::pseudoInverse(real svThreshold) const {
  if (rows_ < cols_) return t().pseudoInverse(svThreshold).t();
  vpMatrix U(*this), V;
  vpColVector w;
  U.svd(w, V);
  const real limit = w.getRows() > 0 ? w[0] * svThreshold : real(0);
  vpMatrix P(cols_, rows_);
  for (unsigned int k = 0; k < cols_; ++k) {
    if (!(w[k] > limit)) continue;
    for (unsigned int r = 0; r < cols_; ++r) {
      const real vk = V[r][k] / w[k];
      for (unsigned int c = 0; c < rows_; ++c) P[r][c] += vk * U[c][k];
    }
  }
  return P;
}

unsigned int vpMatrix::nullSpace(vpMatrix& kerA, int dim) const {
  const unsigned int n = cols_;
  // The SVD needs at least as many rows as columns: pad with zero rows, as upstream.
  vpMatrix U(rows_ < n ? n : rows_, n);
  U.insert(*this, 0, 0);
  vpMatrix V;
  vpColVector w;
  U.svd(w, V);
  const unsigned int d = static_cast<unsigned int>(dim);
  kerA.resize(n, d);
  for (unsigned int k = 0; k < d; ++k)
    for (unsigned int r = 0; r < n; ++r) kerA[r][k] = V[r][n - d + k];
  unsigned int rank = 0;
  for (unsigned int k = 0; k < n; ++k)
    if (w[k] > w[0] * real(1e-6)) ++rank;
  return n - rank;
}

}  // inline namespace edgetrack_ports
