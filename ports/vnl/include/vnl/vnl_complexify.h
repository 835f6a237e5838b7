// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_complexify.h: complex containers from a real part (and an
/// imaginary part).
#pragma once

#ifdef vnl_complexify_h_
#error "edgetrack's drop-in vnl/vnl_complexify.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cassert>
#include <complex>

#include "vnl/vnl_diag_matrix.h"
#include "vnl/vnl_diag_matrix_fixed.h"
#include "vnl/vnl_matrix.h"
#include "vnl/vnl_matrix_fixed.h"
#include "vnl/vnl_sym_matrix.h"
#include "vnl/vnl_vector.h"
#include "vnl/vnl_vector_fixed.h"

inline namespace edgetrack_ports {

template <class T>
void vnl_complexify(const T* R, const T* I, std::complex<T>* C, unsigned n) {
  for (unsigned i = 0; i < n; ++i) C[i] = std::complex<T>(R[i], I[i]);
}
template <class T>
void vnl_complexify(const T* R, std::complex<T>* C, unsigned n) {
  for (unsigned i = 0; i < n; ++i) C[i] = std::complex<T>(R[i], T(0));
}
template <class T>
vnl_vector<std::complex<T>> vnl_complexify(const vnl_vector<T>& R) {
  vnl_vector<std::complex<T>> C(R.size());
  vnl_complexify(R.data_block(), C.data_block(), static_cast<unsigned>(R.size()));
  return C;
}
template <class T>
vnl_vector<std::complex<T>> vnl_complexify(const vnl_vector<T>& R, const vnl_vector<T>& I) {
  assert(R.size() == I.size());
  vnl_vector<std::complex<T>> C(R.size());
  vnl_complexify(R.data_block(), I.data_block(), C.data_block(), static_cast<unsigned>(R.size()));
  return C;
}
template <class T, unsigned n>
vnl_vector_fixed<std::complex<T>, n> vnl_complexify(const vnl_vector_fixed<T, n>& R) {
  vnl_vector_fixed<std::complex<T>, n> C;
  vnl_complexify(R.data_block(), C.data_block(), n);
  return C;
}
template <class T>
vnl_matrix<std::complex<T>> vnl_complexify(const vnl_matrix<T>& R) {
  vnl_matrix<std::complex<T>> C(R.rows(), R.cols());
  vnl_complexify(R.data_block(), C.data_block(), static_cast<unsigned>(R.size()));
  return C;
}
template <class T>
vnl_matrix<std::complex<T>> vnl_complexify(const vnl_matrix<T>& R, const vnl_matrix<T>& I) {
  assert(R.rows() == I.rows() && R.cols() == I.cols());
  vnl_matrix<std::complex<T>> C(R.rows(), R.cols());
  vnl_complexify(R.data_block(), I.data_block(), C.data_block(), static_cast<unsigned>(R.size()));
  return C;
}
template <class T, unsigned r, unsigned c>
vnl_matrix_fixed<std::complex<T>, r, c> vnl_complexify(const vnl_matrix_fixed<T, r, c>& R) {
  vnl_matrix_fixed<std::complex<T>, r, c> C;
  vnl_complexify(R.data_block(), C.data_block(), r * c);
  return C;
}

template <class T, unsigned n>
vnl_vector_fixed<std::complex<T>, n> vnl_complexify(const vnl_vector_fixed<T, n>& R, const vnl_vector_fixed<T, n>& I) {
  vnl_vector_fixed<std::complex<T>, n> C;
  vnl_complexify(R.data_block(), I.data_block(), C.data_block(), n);
  return C;
}
template <class T, unsigned r, unsigned c>
vnl_matrix_fixed<std::complex<T>, r, c> vnl_complexify(const vnl_matrix_fixed<T, r, c>& R,
                                                       const vnl_matrix_fixed<T, r, c>& I) {
  vnl_matrix_fixed<std::complex<T>, r, c> C;
  vnl_complexify(R.data_block(), I.data_block(), C.data_block(), r * c);
  return C;
}
/// The diagonal and symmetric forms, as upstream's: the stored elements complexified.
template <class T>
vnl_diag_matrix<std::complex<T>> vnl_complexify(const vnl_diag_matrix<T>& R) {
  return vnl_diag_matrix<std::complex<T>>(vnl_complexify(R.diagonal()));
}
template <class T>
vnl_diag_matrix<std::complex<T>> vnl_complexify(const vnl_diag_matrix<T>& R, const vnl_diag_matrix<T>& I) {
  return vnl_diag_matrix<std::complex<T>>(vnl_complexify(R.diagonal(), I.diagonal()));
}
template <class T, unsigned n>
vnl_diag_matrix_fixed<std::complex<T>, n> vnl_complexify(const vnl_diag_matrix_fixed<T, n>& R) {
  return vnl_diag_matrix_fixed<std::complex<T>, n>(vnl_complexify(R.diagonal()));
}
template <class T, unsigned n>
vnl_diag_matrix_fixed<std::complex<T>, n> vnl_complexify(const vnl_diag_matrix_fixed<T, n>& R,
                                                         const vnl_diag_matrix_fixed<T, n>& I) {
  return vnl_diag_matrix_fixed<std::complex<T>, n>(vnl_complexify(R.diagonal(), I.diagonal()));
}
template <class T>
vnl_sym_matrix<std::complex<T>> vnl_complexify(const vnl_sym_matrix<T>& R) {
  vnl_sym_matrix<std::complex<T>> C(R.rows());
  vnl_complexify(R.begin(), C.begin(), static_cast<unsigned>(R.end() - R.begin()));
  return C;
}
template <class T>
vnl_sym_matrix<std::complex<T>> vnl_complexify(const vnl_sym_matrix<T>& R, const vnl_sym_matrix<T>& I) {
  assert(R.rows() == I.rows());
  vnl_sym_matrix<std::complex<T>> C(R.rows());
  vnl_complexify(R.begin(), I.begin(), C.begin(), static_cast<unsigned>(R.end() - R.begin()));
  return C;
}

}  // inline namespace edgetrack_ports
