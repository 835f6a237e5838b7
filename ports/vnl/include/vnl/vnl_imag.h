// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_imag.h: the imag parts of complex arrays, vectors and matrices.
#pragma once

#ifdef vnl_imag_h_
#error "edgetrack's drop-in vnl/vnl_imag.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

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
void vnl_imag(const std::complex<T>* C, T* R, unsigned int n) {
  for (unsigned i = 0; i < n; ++i) R[i] = std::imag(C[i]);
}
template <class T>
vnl_vector<T> vnl_imag(const vnl_vector<std::complex<T>>& C) {
  vnl_vector<T> R(C.size());
  vnl_imag(C.data_block(), R.data_block(), static_cast<unsigned>(C.size()));
  return R;
}
template <class T, unsigned int N>
vnl_vector_fixed<T, N> vnl_imag(const vnl_vector_fixed<std::complex<T>, N>& C) {
  vnl_vector_fixed<T, N> R;
  vnl_imag(C.data_block(), R.data_block(), N);
  return R;
}
template <class T>
vnl_matrix<T> vnl_imag(const vnl_matrix<std::complex<T>>& C) {
  vnl_matrix<T> R(C.rows(), C.cols());
  vnl_imag(C.data_block(), R.data_block(), static_cast<unsigned>(C.size()));
  return R;
}
template <class T, unsigned int NRow, unsigned int NCol>
vnl_matrix_fixed<T, NRow, NCol> vnl_imag(const vnl_matrix_fixed<std::complex<T>, NRow, NCol>& C) {
  vnl_matrix_fixed<T, NRow, NCol> R;
  vnl_imag(C.data_block(), R.data_block(), NRow * NCol);
  return R;
}

/// The diagonal and symmetric forms, as upstream's: the stored elements' imag parts.
template <class T>
vnl_diag_matrix<T> vnl_imag(const vnl_diag_matrix<std::complex<T>>& C) {
  return vnl_diag_matrix<T>(vnl_imag(C.diagonal()));
}
template <class T, unsigned int N>
vnl_diag_matrix_fixed<T, N> vnl_imag(const vnl_diag_matrix_fixed<std::complex<T>, N>& C) {
  return vnl_diag_matrix_fixed<T, N>(vnl_imag(C.diagonal()));
}
template <class T>
vnl_sym_matrix<T> vnl_imag(const vnl_sym_matrix<std::complex<T>>& C) {
  vnl_sym_matrix<T> R(C.rows());
  vnl_imag(C.begin(), R.begin(), static_cast<unsigned>(C.end() - C.begin()));
  return R;
}

}  // inline namespace edgetrack_ports
