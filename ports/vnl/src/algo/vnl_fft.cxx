// SPDX-License-Identifier: BSD-3-Clause
/// The FFT engine behind vnl_fft_1d, vnl_fft_2d and vnl_fft_gpfa: mixed-radix (2, 3, 5)
/// decimation in time, recursive over the radices, out of place into a scratch buffer; each
/// sequence is gathered from its stride, transformed and scattered back. Upstream uses
/// Temperton's GPFA; the results are the same transform, to rounding.
#include "vnl/algo/vnl_fft.h"

#include <cmath>
#include <complex>
#include <vector>

#include "vnl/algo/vnl_fft_1d.h"
#include "vnl/algo/vnl_fft_2d.h"
#include "vnl/algo/vnl_fft_base.h"
#include "vnl/algo/vnl_fft_prime_factors.h"

inline namespace edgetrack_ports {

namespace {

/// N as 2^p 3^q 5^r; false when another prime divides N or N < 1.
bool split_235(long N, long pqr[3]) {
  pqr[0] = pqr[1] = pqr[2] = 0;
  if (N < 1) return false;
  const long primes[3] = {2, 3, 5};
  for (int f = 0; f < 3; ++f) {
    while (N % primes[f] == 0) {
      N /= primes[f];
      ++pqr[f];
    }
  }
  return N == 1;
}

template <class T>
void fill_table(T* triggs, long N) {
  const double two_pi = 2 * std::acos(-1.0);
  for (long k = 0; k < N; ++k) {
    triggs[2 * k] = static_cast<T>(std::cos(two_pi * static_cast<double>(k) / static_cast<double>(N)));
    triggs[2 * k + 1] = static_cast<T>(std::sin(two_pi * static_cast<double>(k) / static_cast<double>(N)));
  }
}

/// One transform of length N over the radices of pqr, using the table of vnl_fft_setgpfa.
template <class T>
class Transform {
 public:
  Transform(const T* triggs, long N, const long pqr[3], int dir) : triggs_(triggs), n_(static_cast<int>(N)), dir_(dir) {
    const int primes[3] = {2, 3, 5};
    for (int f = 0; f < 3; ++f)
      for (long e = 0; e < pqr[f]; ++e) radices_.push_back(primes[f]);
    scratch_.resize(static_cast<size_t>(n_));
  }

  /// Transforms the n values in place.
  void run(std::complex<T>* values) {
    recurse(values, 1, scratch_.data(), n_, 0);
    for (int k = 0; k < n_; ++k) values[k] = scratch_[static_cast<size_t>(k)];
  }

 private:
  /// exp(dir 2 pi i e / N).
  std::complex<T> twiddle(long e) const {
    long index = (dir_ * e) % n_;
    if (index < 0) index += n_;
    return {triggs_[2 * index], triggs_[2 * index + 1]};
  }

  /// out[0..n) = the DFT of in[0], in[stride], ..., of length n, splitting off radices_[level].
  void recurse(const std::complex<T>* in, int stride, std::complex<T>* out, int n, size_t level) {
    if (n == 1) {
      out[0] = in[0];
      return;
    }
    const int r = radices_[level], m = n / r;
    for (int s = 0; s < r; ++s) recurse(in + s * stride, stride * r, out + s * m, m, level + 1);
    const long step = n_ / n;  // the table index of exp(2 pi i / n)
    std::complex<T> twiddled[5];
    for (int k = 0; k < m; ++k) {
      for (int s = 0; s < r; ++s) twiddled[s] = out[s * m + k] * twiddle(static_cast<long>(s) * k * step);
      for (int q = 0; q < r; ++q) {
        std::complex<T> sum = twiddled[0];
        for (int s = 1; s < r; ++s) sum += twiddled[s] * twiddle(static_cast<long>((s * q) % r) * m * step);
        out[q * m + k] = sum;
      }
    }
  }

  const T* triggs_;
  int n_;
  int dir_;
  std::vector<int> radices_;
  std::vector<std::complex<T>> scratch_;
};

template <class T>
void setgpfa(T* triggs, long size, long pqr[3], long* info) {
  if (!split_235(size, pqr)) {
    *info = -1;
    return;
  }
  fill_table(triggs, size);
  *info = 0;
}

template <class T>
void gpfa(T* a, T* b, const T* triggs, long inc, long jump, long n, long lot, long isign, const long pqr[3],
          long* info) {
  long check[3];
  if (!split_235(n, check) || (isign != 1 && isign != -1)) {
    *info = -1;
    return;
  }
  Transform<T> transform(triggs, n, pqr, static_cast<int>(isign));
  std::vector<std::complex<T>> values(static_cast<size_t>(n));
  for (long l = 0; l < lot; ++l) {
    for (long j = 0; j < n; ++j) values[static_cast<size_t>(j)] = {a[l * jump + j * inc], b[l * jump + j * inc]};
    transform.run(values.data());
    for (long j = 0; j < n; ++j) {
      a[l * jump + j * inc] = values[static_cast<size_t>(j)].real();
      b[l * jump + j * inc] = values[static_cast<size_t>(j)].imag();
    }
  }
  *info = 0;
}

}  // namespace

void vnl_fft_setgpfa(float* triggs, long size, long pqr[3], long* info) { setgpfa(triggs, size, pqr, info); }
void vnl_fft_setgpfa(double* triggs, long size, long pqr[3], long* info) { setgpfa(triggs, size, pqr, info); }
void vnl_fft_gpfa(float* a, float* b, const float* triggs, long inc, long jump, long n, long lot, long isign,
                  const long pqr[3], long* info) {
  gpfa(a, b, triggs, inc, jump, n, lot, isign, pqr, info);
}
void vnl_fft_gpfa(double* a, double* b, const double* triggs, long inc, long jump, long n, long lot, long isign,
                  const long pqr[3], long* info) {
  gpfa(a, b, triggs, inc, jump, n, lot, isign, pqr, info);
}

template <class T>
void vnl_fft_prime_factors<T>::construct(int N) {
  number_ = N;
  trigs_.clear();
  info_ = -1;
  if (N < 1) return;
  trigs_.resize(2 * static_cast<size_t>(N));
  vnl_fft_setgpfa(trigs_.data(), number_, pqr_.data(), &info_);
  if (info_ < 0) trigs_.clear();
}

template <int D, class T>
void vnl_fft_base<D, T>::transform(std::complex<T>* signal, int dir) {
  // Along dimension i the array is N1 x N2 x N3 with N2 = n[i]: N1 N3 sequences of stride N3.
  for (int i = 0; i < D; ++i) {
    if (!factors_[i]) return;
    long N1 = 1, N2 = factors_[i].number(), N3 = 1;
    for (int j = 0; j < i; ++j) N1 *= factors_[j].number();
    for (int j = i + 1; j < D; ++j) N3 *= factors_[j].number();
    Transform<T> transform(factors_[i].trigs(), N2, factors_[i].pqr(), dir);
    std::vector<std::complex<T>> values(static_cast<size_t>(N2));
    for (long n1 = 0; n1 < N1; ++n1) {
      for (long n3 = 0; n3 < N3; ++n3) {
        std::complex<T>* first = signal + n1 * N2 * N3 + n3;
        for (long k = 0; k < N2; ++k) values[static_cast<size_t>(k)] = first[k * N3];
        transform.run(values.data());
        for (long k = 0; k < N2; ++k) first[k * N3] = values[static_cast<size_t>(k)];
      }
    }
  }
}

template struct vnl_fft_prime_factors<float>;
template struct vnl_fft_prime_factors<double>;
template struct vnl_fft_base<1, float>;
template struct vnl_fft_base<1, double>;
template struct vnl_fft_base<2, float>;
template struct vnl_fft_base<2, double>;

}  // inline namespace edgetrack_ports
