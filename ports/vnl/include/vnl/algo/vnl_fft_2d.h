// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_fft_2d.h: the in-place 2-D DFT of an M x N complex matrix,
/// M and N each 2^p 3^q 5^r (see vnl_fft_base.h for the sign; no normalisation).
#pragma once

#ifdef vnl_fft_2d_h_
#error "edgetrack's drop-in vnl/algo/vnl_fft_2d.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <complex>

#include "vnl/algo/vnl_fft_base.h"
#include "vnl/vnl_matrix.h"

inline namespace edgetrack_ports {

template <class T>
struct vnl_fft_2d : public vnl_fft_base<2, T> {
  using base = vnl_fft_base<2, T>;

  vnl_fft_2d(int M, int N) {
    base::factors_[0].resize(M);
    base::factors_[1].resize(N);
  }
  void transform(vnl_matrix<std::complex<T>>& signal, int dir) { base::transform(signal.data_block(), dir); }
  void fwd_transform(vnl_matrix<std::complex<T>>& signal) { transform(signal, +1); }
  void bwd_transform(vnl_matrix<std::complex<T>>& signal) { transform(signal, -1); }
  unsigned rows() const { return static_cast<unsigned>(base::factors_[0].number()); }
  unsigned cols() const { return static_cast<unsigned>(base::factors_[1].number()); }
};

}  // inline namespace edgetrack_ports
