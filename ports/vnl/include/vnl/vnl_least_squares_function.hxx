// SPDX-License-Identifier: BSD-3-Clause
/// Definitions for vnl_least_squares_function.h. Include it only to instantiate the class for a
/// scalar that the library does not instantiate.
#pragma once

#include <cmath>
#include <limits>

#include "vnl/vnl_least_squares_function.h"
#include "vnl/vnl_matrix.hxx"
#include "vnl/vnl_vector.hxx"

inline namespace edgetrack_ports {

template <class T>
void vnl_least_squares_function_of<T>::gradf(const vnl_vector<T>& x, vnl_matrix<T>& jacobian) {
  using std::sqrt;
  ffdgradf(x, jacobian, sqrt(std::numeric_limits<T>::epsilon()));
}

template <class T>
void vnl_least_squares_function_of<T>::fdgradf(const vnl_vector<T>& x, vnl_matrix<T>& jacobian, T stepsize) {
  vnl_vector<T> fplus(n_);
  vnl_vector<T> fminus(n_);
  vnl_vector<T> shifted = x;
  jacobian.set_size(n_, p_);
  for (unsigned int j = 0; j < p_; ++j) {
    const T plus = shifted[j] = x[j] + stepsize;
    f(shifted, fplus);
    const T minus = shifted[j] = x[j] - stepsize;
    f(shifted, fminus);
    shifted[j] = x[j];
    // Divided by the step actually taken, which rounding may make differ from 2 * stepsize.
    for (unsigned int i = 0; i < n_; ++i) jacobian(i, j) = (fplus[i] - fminus[i]) / (plus - minus);
  }
}

template <class T>
void vnl_least_squares_function_of<T>::ffdgradf(const vnl_vector<T>& x, vnl_matrix<T>& jacobian, T stepsize) {
  vnl_vector<T> fx(n_);
  vnl_vector<T> fplus(n_);
  vnl_vector<T> shifted = x;
  f(x, fx);
  jacobian.set_size(n_, p_);
  for (unsigned int j = 0; j < p_; ++j) {
    const T plus = shifted[j] = x[j] + stepsize;
    f(shifted, fplus);
    shifted[j] = x[j];
    for (unsigned int i = 0; i < n_; ++i) jacobian(i, j) = (fplus[i] - fx[i]) / (plus - x[j]);
  }
}

template <class T>
void vnl_least_squares_function_of<T>::trace(int, const vnl_vector<T>&, const vnl_vector<T>&) {}

template <class T>
T vnl_least_squares_function_of<T>::rms(const vnl_vector<T>& x) {
  vnl_vector<T> fx(n_);
  f(x, fx);
  return fx.rms();
}

#define VNL_LEAST_SQUARES_FUNCTION_INSTANTIATE(T) template class vnl_least_squares_function_of<T>

}  // inline namespace edgetrack_ports
