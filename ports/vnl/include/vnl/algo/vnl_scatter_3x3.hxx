// SPDX-License-Identifier: BSD-3-Clause
/// Definitions for vnl_scatter_3x3.h. Include it only to instantiate the class for a scalar that
/// the library does not instantiate.
#pragma once

#include <iostream>

#include "vnl/algo/vnl_scatter_3x3.h"
#include "vnl/algo/vnl_symmetric_eigensystem.h"

inline namespace edgetrack_ports {

template <class T>
void vnl_scatter_3x3<T>::add_outer_product(const vnl_vector_fixed<T, 3>& v) {
  for (unsigned i = 0; i < 3; ++i) {
    (*this)(i, i) += v[i] * v[i];
    for (unsigned j = i + 1; j < 3; ++j) {
      (*this)(i, j) += v[i] * v[j];
      (*this)(j, i) = (*this)(i, j);
    }
  }
  eigenvectors_currentp = false;
}

template <class T>
void vnl_scatter_3x3<T>::add_outer_product(const vnl_vector_fixed<T, 3>& u, const vnl_vector_fixed<T, 3>& v) {
  for (unsigned i = 0; i < 3; ++i)
    for (unsigned j = 0; j < 3; ++j) (*this)(i, j) += v[i] * u[j];
  symmetricp = false;
  eigenvectors_currentp = false;
}

template <class T>
void vnl_scatter_3x3<T>::sub_outer_product(const vnl_vector_fixed<T, 3>& v) {
  for (unsigned i = 0; i < 3; ++i) {
    (*this)(i, i) -= v[i] * v[i];
    for (unsigned j = i + 1; j < 3; ++j) {
      (*this)(i, j) -= v[i] * v[j];
      (*this)(j, i) = (*this)(i, j);
    }
  }
  eigenvectors_currentp = false;
}

template <class T>
void vnl_scatter_3x3<T>::sub_outer_product(const vnl_vector_fixed<T, 3>& u, const vnl_vector_fixed<T, 3>& v) {
  for (unsigned i = 0; i < 3; ++i)
    for (unsigned j = 0; j < 3; ++j) (*this)(i, j) -= v[i] * u[j];
  symmetricp = false;
  eigenvectors_currentp = false;
}

template <class T>
void vnl_scatter_3x3<T>::force_symmetric() {
  if (symmetricp) return;
  for (unsigned i = 0; i < 3; ++i)
    for (unsigned j = i + 1; j < 3; ++j) (*this)(i, j) = (*this)(j, i) = ((*this)(i, j) + (*this)(j, i)) / T(2);
  symmetricp = true;
  eigenvectors_currentp = false;
}

template <class T>
void vnl_scatter_3x3<T>::compute_eigensystem() {
  if (symmetricp) {
    vnl_matrix<T> vectors;
    vnl_vector<T> values;
    vnl_symmetric_eigensystem_compute(this->as_matrix(), vectors, values);
    V_ = vnl_matrix_fixed<T, 3, 3>(vectors.data_block());
    D = vnl_vector_fixed<T, 3>(values.data_block());
  } else {
    std::cerr << "Asymmetric scatter not handled now\n";
  }
  eigenvectors_currentp = true;
}

#define VNL_SCATTER_3X3_INSTANTIATE(T) template class vnl_scatter_3x3<T>

}  // inline namespace edgetrack_ports
