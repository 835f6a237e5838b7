// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_fft_prime_factors.h: a length N = 2^P 3^Q 5^R split into its
/// exponents, with the twiddle table of vnl_fft_setgpfa. It converts to false when N has another
/// prime factor (or is not positive). Not copyable, as upstream.
#pragma once

#ifdef vnl_fft_prime_factors_h_
#error "edgetrack's drop-in vnl/algo/vnl_fft_prime_factors.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <array>
#include <vector>

inline namespace edgetrack_ports {

template <class T>
struct vnl_fft_prime_factors {
  vnl_fft_prime_factors() = default;
  explicit vnl_fft_prime_factors(int N) { construct(N); }
  vnl_fft_prime_factors(const vnl_fft_prime_factors&) = delete;
  vnl_fft_prime_factors& operator=(const vnl_fft_prime_factors&) = delete;

  /// The table: cos and sin of 2 pi k / N for k = 0 .. N-1, interleaved.
  const T* trigs() const { return trigs_.empty() ? nullptr : trigs_.data(); }
  int number() const { return static_cast<int>(number_); }
  /// P, Q and R.
  const long* pqr() const { return pqr_.data(); }
  explicit operator bool() const { return !trigs_.empty() && info_ >= 0; }
  bool operator!() const { return !static_cast<bool>(*this); }
  void resize(int N) { construct(N); }

 private:
  void construct(int N);

  std::vector<T> trigs_;
  long number_ = 0;
  std::array<long, 3> pqr_{};
  long info_ = -1;
};

}  // inline namespace edgetrack_ports
