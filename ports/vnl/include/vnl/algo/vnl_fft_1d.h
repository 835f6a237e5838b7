// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_fft_1d.h: the in-place DFT of a sequence of N = 2^p 3^q 5^r
/// complex values (see vnl_fft_base.h for the sign; no normalisation, so bwd(fwd(x)) = N x).
#pragma once

#ifdef vnl_fft_1d_h_
#error "edgetrack's drop-in vnl/algo/vnl_fft_1d.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <complex>
#include <vector>

#include "vnl/algo/vnl_fft_base.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

template <class T>
struct vnl_fft_1d : public vnl_fft_base<1, T> {
  using base = vnl_fft_base<1, T>;

  explicit vnl_fft_1d(int N) { base::factors_[0].resize(N); }
  unsigned int size() const { return static_cast<unsigned int>(base::factors_[0].number()); }

  void transform(std::vector<std::complex<T>>& signal, int dir) { base::transform(signal.data(), dir); }
  void transform(std::complex<T>* signal, int dir) { base::transform(signal, dir); }
  void transform(vnl_vector<std::complex<T>>& signal, int dir) { base::transform(signal.data_block(), dir); }
  void fwd_transform(std::vector<std::complex<T>>& signal) { transform(signal, +1); }
  void fwd_transform(std::complex<T>* signal) { transform(signal, +1); }
  void fwd_transform(vnl_vector<std::complex<T>>& signal) { transform(signal, +1); }
  void bwd_transform(std::vector<std::complex<T>>& signal) { transform(signal, -1); }
  void bwd_transform(std::complex<T>* signal) { transform(signal, -1); }
  void bwd_transform(vnl_vector<std::complex<T>>& signal) { transform(signal, -1); }
};

}  // inline namespace edgetrack_ports
