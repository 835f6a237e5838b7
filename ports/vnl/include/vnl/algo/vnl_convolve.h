// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_convolve.h: the full convolution of two vectors
/// (length n1 + n2 - 1) and the cyclic one of two vectors of one length, directly or, with
/// use_fft, through vnl_fft_1d in double: use_fft != 0 is the FFT length wanted, raised to at
/// least n1 + n2 - 1 and then to the next 2^p 3^q 5^r. The U* argument only names the result
/// type; a cyclic length with another prime factor is convolved directly. Upstream declares
/// matrix forms it never defines; they are left out here.
#pragma once

#ifdef vnl_convolve_h_
#error "edgetrack's drop-in vnl/algo/vnl_convolve.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <complex>

#include "vnl/algo/vnl_fft_1d.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

namespace vnl_convolve_detail {

inline bool has_only_primefactors_2_3_5(unsigned int n) {
  if (n <= 1) return true;
  for (unsigned int p : {2u, 3u, 5u})
    while (n % p == 0) n /= p;
  return n == 1;
}

/// The cyclic convolution of two vectors of length n by the DFT: bwd(fwd(v1) fwd(v2)) / n.
template <class T1, class T2, class U>
vnl_vector<U> cyclic_using_fft(const vnl_vector<T1>& v1, const vnl_vector<T2>& v2, unsigned int n) {
  using C = std::complex<double>;
  vnl_vector<C> w1(n, C(0)), w2(n, C(0));
  for (unsigned int i = 0; i < v1.size() && i < n; ++i) w1[i] = C(static_cast<double>(v1[i]));
  for (unsigned int i = 0; i < v2.size() && i < n; ++i) w2[i] = C(static_cast<double>(v2[i]));
  vnl_fft_1d<double> fft(static_cast<int>(n));
  fft.fwd_transform(w1);
  fft.fwd_transform(w2);
  for (unsigned int i = 0; i < n; ++i) w1[i] *= w2[i];
  fft.bwd_transform(w1);
  vnl_vector<U> r(n);
  for (unsigned int i = 0; i < n; ++i) r[i] = U(w1[i].real() / n);
  return r;
}

template <class T1, class T2, class U>
vnl_vector<U> full_using_fft(const vnl_vector<T1>& v1, const vnl_vector<T2>& v2, int n) {
  const unsigned int length = v1.size() + v2.size() - 1;
  unsigned int size = n > 0 && static_cast<unsigned int>(n) >= length ? static_cast<unsigned int>(n) : length;
  while (!has_only_primefactors_2_3_5(size)) ++size;
  const vnl_vector<U> cyclic = cyclic_using_fft<T1, T2, U>(v1, v2, size);
  return vnl_vector<U>(length, length, cyclic.data_block());
}

template <class T1, class T2, class U>
vnl_vector<U> full_direct(const vnl_vector<T1>& v1, const vnl_vector<T2>& v2) {
  const unsigned int n1 = v1.size(), n2 = v2.size();
  vnl_vector<U> r(n1 + n2 - 1, U(0));
  for (unsigned int i = 0; i < n1; ++i)
    for (unsigned int j = 0; j < n2; ++j) r[i + j] += U(v1[i]) * U(v2[j]);
  return r;
}

}  // namespace vnl_convolve_detail

template <class T1, class T2, class U>
vnl_vector<U> vnl_convolve(const vnl_vector<T1>& v1, const vnl_vector<T2>& v2, U*, int use_fft = 0) {
  if (v1.empty() || v2.empty()) return vnl_vector<U>(0);
  if (use_fft != 0) return vnl_convolve_detail::full_using_fft<T1, T2, U>(v1, v2, use_fft);
  return vnl_convolve_detail::full_direct<T1, T2, U>(v1, v2);
}

template <class T>
vnl_vector<T> vnl_convolve(const vnl_vector<T>& v1, const vnl_vector<T>& v2, int use_fft = 0) {
  return vnl_convolve(v1, v2, static_cast<T*>(nullptr), use_fft);
}

/// r[k] = sum_i v1[(k - i) mod n] v2[i], for v1 and v2 of one length n.
template <class T1, class T2, class U>
vnl_vector<U> vnl_convolve_cyclic(const vnl_vector<T1>& v1, const vnl_vector<T2>& v2, U*, bool use_fft = false) {
  const unsigned int n = v1.size();
  if (n == 0 || v2.size() != n) return vnl_vector<U>(0, U(0));
  if (use_fft && n > 1 && vnl_convolve_detail::has_only_primefactors_2_3_5(n))
    return vnl_convolve_detail::cyclic_using_fft<T1, T2, U>(v1, v2, n);
  vnl_vector<U> r(n, U(0));
  for (unsigned int k = 0; k < n; ++k)
    for (unsigned int i = 0; i < n; ++i) r[k] += U(v1[(k + n - i) % n]) * U(v2[i]);
  return r;
}

}  // inline namespace edgetrack_ports
