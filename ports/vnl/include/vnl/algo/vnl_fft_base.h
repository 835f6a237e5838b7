// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_fft_base.h: the D-dimensional discrete Fourier transform of
/// a row-major array of D lengths, each 2^p 3^q 5^r, done one dimension after the other in
/// place. dir = +1: X(j) = sum_k x(k) exp(+2 pi i j k / N) (upstream's "forward", GPFA's sign);
/// dir = -1 the conjugate; neither divides by N.
#pragma once

#ifdef vnl_fft_base_h_
#error "edgetrack's drop-in vnl/algo/vnl_fft_base.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <complex>

#include "vnl/algo/vnl_fft_prime_factors.h"

inline namespace edgetrack_ports {

template <int D, class T>
struct vnl_fft_base {
  vnl_fft_base() = default;
  void transform(std::complex<T>* signal, int dir);

 protected:
  vnl_fft_prime_factors<T> factors_[D];
};

}  // inline namespace edgetrack_ports
