// SPDX-License-Identifier: BSD-3-Clause
/// Definitions for vnl_svd.h: our one-sided Jacobi SVD (see vnl_svd.h).
#pragma once

#include <cmath>
#include <limits>
#include <ostream>
#include <utility>

#include "vnl/algo/vnl_jacobi_rotation.h"
#include "vnl/algo/vnl_svd.h"
#include "vnl/vnl_math.h"

inline namespace edgetrack_ports {

namespace vnl_svd_detail {
/// Rotates columns p and q of m by (c, s): (p, q) <- (c p - s q, s p + c q).
template <class T>
void rotate_columns(vnl_matrix<T>& m, unsigned p, unsigned q, const T& c, const T& s) {
  for (unsigned i = 0; i < m.rows(); ++i) {
    const T mp = m(i, p), mq = m(i, q);
    m(i, p) = c * mp - s * mq;
    m(i, q) = s * mp + c * mq;
  }
}

template <class T>
void swap_columns(vnl_matrix<T>& m, unsigned a, unsigned b) {
  for (unsigned i = 0; i < m.rows(); ++i) std::swap(m(i, a), m(i, b));
}
}  // namespace vnl_svd_detail

template <class T>
vnl_svd<T>::vnl_svd(const vnl_matrix<T>& M, double zero_out_tol)
    : m_(static_cast<unsigned>(M.rows())),
      n_(static_cast<unsigned>(M.cols())),
      U_(M),
      W_(n_),
      Winverse_(n_),
      V_(n_, n_) {
  using std::sqrt;
  V_.set_identity();
  const T eps = std::numeric_limits<T>::epsilon();
  const T large_zeta = T(1) / sqrt(eps);
  const T absolute_floor = vnl_jacobi::rounding_floor<T>(m_);
  bool rotated = true;
  int sweep = 0;
  for (; sweep < vnl_jacobi::kMaxSweeps && rotated; ++sweep) {
    rotated = false;
    for (unsigned p = 0; p + 1 < n_; ++p) {
      for (unsigned q = p + 1; q < n_; ++q) {
        T alpha(0), beta(0), gamma(0);
        for (unsigned i = 0; i < m_; ++i) {
          alpha += U_(i, p) * U_(i, p);
          beta += U_(i, q) * U_(i, q);
          gamma += U_(i, p) * U_(i, q);
        }
        const T magnitude = vnl_math::abs(gamma);
        if (magnitude <= absolute_floor || magnitude <= eps * sqrt(alpha) * sqrt(beta)) continue;
        const T t = vnl_jacobi::tangent(alpha, beta, gamma, large_zeta);
        const T c = T(1) / sqrt(T(1) + t * t);
        const T s = c * t;
        vnl_svd_detail::rotate_columns(U_, p, q, c, s);
        vnl_svd_detail::rotate_columns(V_, p, q, c, s);
        rotated = true;
      }
    }
  }
  valid_ = !rotated;
  // The column norms are the singular values; the normalised columns are U's.
  for (unsigned j = 0; j < n_; ++j) {
    T total(0);
    for (unsigned i = 0; i < m_; ++i) total += U_(i, j) * U_(i, j);
    const T w = sqrt(total);
    W_[j] = w;
    if (w != T(0)) {
      for (unsigned i = 0; i < m_; ++i) U_(i, j) /= w;
    }
  }
  for (unsigned j = 0; j + 1 < n_; ++j) {  // descending order, as LINPACK returns them
    unsigned largest = j;
    for (unsigned k = j + 1; k < n_; ++k) {
      if (W_[k] > W_[largest]) largest = k;
    }
    if (largest == j) continue;
    std::swap(W_[j], W_[largest]);
    vnl_svd_detail::swap_columns(U_, j, largest);
    vnl_svd_detail::swap_columns(V_, j, largest);
  }
  complete_u_basis();
  // A wide matrix has at most m nonzero singular values; the rest are exact zeros, as in
  // LINPACK's result, and their U columns (no room left in m dimensions) are zero.
  for (unsigned j = m_; j < n_; ++j) {
    W_[j] = singval_t(0);
    for (unsigned i = 0; i < m_; ++i) U_(i, j) = T(0);
  }
  if (zero_out_tol >= 0) {
    zero_out_absolute(zero_out_tol);
  } else {
    zero_out_relative(-zero_out_tol);
  }
}

template <class T>
void vnl_svd<T>::complete_u_basis() {
  // A column of U whose singular value is zero to working precision is M v / w with w ~ 0:
  // rounding noise. Replace it, as LINPACK's U would be, by a unit vector orthogonal to the
  // columns before it (Gram-Schmidt, twice, on the first coordinate axis that survives).
  using std::sqrt;
  if (n_ == 0) return;
  const singval_t negligible =
      std::numeric_limits<T>::epsilon() * T(static_cast<int>(m_ > n_ ? m_ : n_)) * W_[0] +
      vnl_jacobi::rounding_floor<T>(m_);
  const unsigned columns = m_ < n_ ? m_ : n_;
  for (unsigned j = 0; j < columns; ++j) {
    if (W_[j] > negligible) continue;
    for (unsigned axis = 0; axis < m_; ++axis) {
      vnl_vector<T> u(m_, T(0));
      u[axis] = T(1);
      for (int pass = 0; pass < 2; ++pass) {
        for (unsigned k = 0; k < j; ++k) {
          T dot(0);
          for (unsigned i = 0; i < m_; ++i) dot += U_(i, k) * u[i];
          for (unsigned i = 0; i < m_; ++i) u[i] -= dot * U_(i, k);
        }
      }
      const T norm = u.two_norm();
      static constexpr T kHalf = T(0.5);
      if (norm < kHalf) continue;  // the axis lies (nearly) in the span so far
      for (unsigned i = 0; i < m_; ++i) U_(i, j) = u[i] / norm;
      break;
    }
  }
}

template <class T>
void vnl_svd<T>::zero_out_below(const singval_t& limit) {
  rank_ = n_;
  for (unsigned k = 0; k < n_; ++k) {
    if (vnl_math::abs(W_[k]) <= limit) {
      W_[k] = singval_t(0);
      Winverse_[k] = singval_t(0);
      --rank_;
    } else {
      Winverse_[k] = singval_t(1) / W_[k];
    }
  }
}

template <class T>
void vnl_svd<T>::zero_out_absolute(double tol) {
  last_tol_ = tol;
  zero_out_below(singval_t(tol));  // one conversion of the caller's double
}

template <class T>
void vnl_svd<T>::zero_out_relative(double tol) {
  last_tol_ = tol;
  zero_out_below(singval_t(tol) * vnl_math::abs(sigma_max()));
}

template <class T>
typename vnl_svd<T>::singval_t vnl_svd<T>::determinant_magnitude() const {
  singval_t product(1);
  for (unsigned k = 0; k < n_; ++k) product *= W_[k];
  return product;
}

namespace vnl_svd_detail {
/// The first `rank` entries of w, the rest zero, as a diagonal matrix.
template <class S>
vnl_matrix<S> truncated(const vnl_diag_matrix<S>& w, unsigned rank) {
  vnl_matrix<S> result(w.size(), w.size(), S(0));
  for (unsigned i = 0; i < w.size() && i < rank; ++i) result(i, i) = w[i];
  return result;
}
}  // namespace vnl_svd_detail

template <class T>
vnl_matrix<T> vnl_svd<T>::pinverse(unsigned int rank) const {
  if (rank > rank_) rank = rank_;
  return V_ * vnl_svd_detail::truncated(Winverse_, rank) * U_.conjugate_transpose();
}

template <class T>
vnl_matrix<T> vnl_svd<T>::tinverse(unsigned int rank) const {
  if (rank > rank_) rank = rank_;
  return U_ * vnl_svd_detail::truncated(Winverse_, rank) * V_.conjugate_transpose();
}

template <class T>
vnl_matrix<T> vnl_svd<T>::recompose(unsigned int rank) const {
  if (rank > rank_) rank = rank_;
  return U_ * vnl_svd_detail::truncated(W_, rank) * V_.conjugate_transpose();
}

template <class T>
vnl_matrix<T> vnl_svd<T>::solve(const vnl_matrix<T>& B) const {
  vnl_matrix<T> x = U_.conjugate_transpose() * B;
  for (unsigned i = 0; i < x.rows(); ++i) x.scale_row(i, Winverse_[i]);
  return V_ * x;
}

template <class T>
vnl_vector<T> vnl_svd<T>::solve(const vnl_vector<T>& y) const {
  vnl_vector<T> x = U_.conjugate_transpose() * y;
  for (unsigned i = 0; i < x.size(); ++i) x[i] *= Winverse_[i];
  return V_ * x;
}

template <class T>
void vnl_svd<T>::solve(const T* rhs, T* lhs) const {
  solve(vnl_vector<T>(rhs, m_)).copy_out(lhs);
}

template <class T>
void vnl_svd<T>::solve_preinverted(const vnl_vector<T>& rhs, vnl_vector<T>* out) const {
  *out = solve(rhs);
}

template <class T>
vnl_matrix<T> vnl_svd<T>::nullspace() const {
  return nullspace(static_cast<int>(n_ - rank_));
}

template <class T>
vnl_matrix<T> vnl_svd<T>::nullspace(int required_nullspace_dimension) const {
  const unsigned k = static_cast<unsigned>(required_nullspace_dimension);
  return V_.extract(V_.rows(), k, 0, n_ - k);
}

template <class T>
vnl_matrix<T> vnl_svd<T>::left_nullspace() const {
  return left_nullspace(static_cast<int>(n_ - rank_));
}

template <class T>
vnl_matrix<T> vnl_svd<T>::left_nullspace(int required_nullspace_dimension) const {
  const unsigned k = static_cast<unsigned>(required_nullspace_dimension);
  return U_.extract(U_.rows(), k, 0, n_ - k);
}

template <class T>
vnl_vector<T> vnl_svd<T>::nullvector() const {
  return V_.get_column(n_ - 1);
}

template <class T>
vnl_vector<T> vnl_svd<T>::left_nullvector() const {
  return U_.get_column(n_ - 1);
}

template <class T>
std::ostream& operator<<(std::ostream& s, const vnl_svd<T>& svd) {
  s << "vnl_svd<T>:\n"
    << "U = [\n" << svd.U() << "]\nW = " << svd.W() << "\nV = [\n" << svd.V() << "]\nrank = " << svd.rank() << '\n';
  return s;
}

#define VNL_SVD_INSTANTIATE(T) \
  template class vnl_svd<T>;   \
  template std::ostream& operator<<(std::ostream&, const vnl_svd<T>&)

}  // inline namespace edgetrack_ports
