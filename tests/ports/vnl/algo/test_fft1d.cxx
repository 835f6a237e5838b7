// SPDX-License-Identifier: BSD-3-Clause
// vnl_fft_1d as upstream's algo test_fft1d.cxx: for lengths 2^p 3^q 5^r from 1 to 625, the
// transform on a vnl_vector, a std::vector and a C array agree, and backward after forward
// gives N times the signal; plus the sign and the factors.
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "testlib/testlib_test.h"
#include "vnl/algo/vnl_fft_1d.h"

namespace {
using C = std::complex<double>;

void test_fft_1d(int n) {
  const std::string in = " (n = " + std::to_string(n) + ")";
  const vnl_fft_prime_factors<double> factors(n);
  TEST("the length splits into 2^P 3^Q 5^R" + in, static_cast<bool>(factors), true);
  vnl_vector<C> array(n);
  std::vector<C> vec(n);
  std::vector<C> ptr(n);
  for (int i = 0; i < n; ++i) array(i) = vec[i] = ptr[i] = C(i - 3.5, 0.0);
  vnl_fft_1d<double> fft(n);
  TEST("size" + in, fft.size(), static_cast<unsigned>(n));
  fft.fwd_transform(array);
  fft.transform(vec, +1);
  fft.fwd_transform(ptr.data());
  bool same = true;
  for (int i = 0; i < n; ++i) same = same && array(i) == vec[i] && vec[i] == ptr[i];
  TEST("forward on vnl_vector, std::vector and a C array agree" + in, same, true);
  fft.bwd_transform(array);
  fft.transform(vec, -1);
  fft.bwd_transform(ptr.data());
  double real_error = 0, imag_error = 0;
  same = true;
  for (int i = 0; i < n; ++i) {
    same = same && array(i) == vec[i] && vec[i] == ptr[i];
    real_error += std::fabs(array(i).real() / n - (i - 3.5));
    imag_error += std::fabs(array(i).imag() / n);
  }
  TEST("backward on the three agree" + in, same, true);
  TEST_NEAR("absolute error, real part (per element)" + in, real_error / n, 0.0, 1e-9);
  TEST_NEAR("absolute error, imag part (per element)" + in, imag_error / n, 0.0, 1e-9);
}
}  // namespace

static void test_fft1d() {
  for (int n : {256, 243, 625, 1, 2, 3, 4, 5, 6, 8, 9, 10, 16, 32, 64, 128, 200, 216, 225, 240, 250, 270, 288})
    test_fft_1d(n);
  // The sign, as GPFA's: forward is sum_k x_k exp(+2 pi i j k / N).
  vnl_fft_1d<double> fft(6);
  std::vector<C> delta(6, C(0));
  delta[1] = 1;
  fft.fwd_transform(delta);
  TEST_NEAR("forward of the unit at k = 1 is exp(+2 pi i j / 6) (real)", delta[1].real(), 0.5, 1e-12);
  TEST_NEAR("forward of the unit at k = 1 is exp(+2 pi i j / 6) (imag)", delta[1].imag(), std::sqrt(3.0) / 2, 1e-12);
  TEST("7 has another prime factor", static_cast<bool>(vnl_fft_prime_factors<double>(7)), false);
  const vnl_fft_prime_factors<float> f360(360);
  TEST("360 = 2^3 3^2 5", f360.pqr()[0] == 3 && f360.pqr()[1] == 2 && f360.pqr()[2] == 1, true);
  vnl_fft_1d<float> single(12);
  std::vector<std::complex<float>> ones(12, std::complex<float>(1));
  single.fwd_transform(ones);
  TEST_NEAR("float: the transform of ones is N at 0", ones[0].real(), 12.0, 1e-5);
  TEST_NEAR("float: and 0 elsewhere", std::abs(ones[5]), 0.0, 1e-5);
}

TESTMAIN(test_fft1d)
