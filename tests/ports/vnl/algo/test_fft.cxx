// SPDX-License-Identifier: BSD-3-Clause
// vnl_fft_1d and vnl_fft_2d as upstream's algo test_fft.cxx: on random signals (length 24, and
// 25 x 30), backward after forward divided by the size gives the signal back.
#include <complex>

#include "testlib/testlib_test.h"
#include "vnl/algo/vnl_fft_1d.h"
#include "vnl/algo/vnl_fft_2d.h"
#include "vnl/vnl_random.h"

namespace {
using C = std::complex<double>;

void test_fft_1d(unsigned int N) {
  vnl_random rng(9667566);
  vnl_vector<C> signal(N);
  for (C& x : signal) x = C(rng.drand64(-1, 1), rng.drand64(-1, 1));
  vnl_fft_1d<double> fft(N);
  vnl_vector<C> tmp = signal;
  fft.fwd_transform(tmp);
  fft.bwd_transform(tmp);
  tmp /= C(N);
  TEST_NEAR("test fwd-bwd (1-D)", (tmp - signal).two_norm(), 0.0, 1e-10);
}

void test_fft_2d(unsigned int M, unsigned int N) {
  vnl_random rng(9667566);
  vnl_matrix<C> signal(M, N);
  for (C& x : signal) x = C(rng.drand64(-1, 1), rng.drand64(-1, 1));
  vnl_fft_2d<double> fft(M, N);
  vnl_matrix<C> tmp = signal;
  fft.fwd_transform(tmp);
  fft.bwd_transform(tmp);
  tmp /= C(M * N);
  TEST_NEAR("test fwd-bwd (2-D)", (tmp - signal).fro_norm(), 0.0, 1e-10);
}
}  // namespace

static void test_fft() {
  test_fft_1d(24);
  test_fft_2d(25, 30);
}

TESTMAIN(test_fft)
