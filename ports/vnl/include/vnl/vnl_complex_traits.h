// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_complex_traits.h: whether a scalar is real or complex, its
/// conjugate, and its complexification.
#pragma once

#ifdef vnl_complex_traits_h_
#error "edgetrack's drop-in vnl/vnl_complex_traits.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <complex>

inline namespace edgetrack_ports {

template <class T>
struct vnl_complex_traits {
  static constexpr bool isreal = true;
  static T conjugate(T x) { return x; }
  static std::complex<T> complexify(T x) { return std::complex<T>(x, T(0)); }
};

template <class T>
struct vnl_complex_traits<std::complex<T>> {
  static constexpr bool isreal = false;
  static std::complex<T> conjugate(std::complex<T> x) { return std::conj(x); }
  static std::complex<T> complexify(std::complex<T> x) { return x; }
};

template <class T>
struct vnl_complex_traits<const T> : vnl_complex_traits<T> {};

}  // inline namespace edgetrack_ports
