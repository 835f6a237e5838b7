// SPDX-License-Identifier: BSD-3-Clause
// vnl_fft_2d as upstream's algo test_fft2d.cxx: on a 64 x 64 matrix i j, both directions change
// it and keep its shape, and backward after forward gives M N times it (to 20 ulps of its norm;
// upstream: 1e-7 absolute); and one element of a transform against its formula.
#include <cmath>
#include <complex>

#include "testlib/testlib_test.h"
#include "vnl/algo/vnl_fft_2d.h"

namespace {
using C = std::complex<double>;

void test_cplx(const vnl_matrix<C>& M, int dir) {
  vnl_matrix<C> fft_matrix = M;
  vnl_fft_2d<double> fft(M.rows(), M.cols());
  fft.transform(fft_matrix, dir);
  TEST("test rows", fft.rows(), M.rows());
  TEST("test cols", fft.cols(), M.cols());
  TEST("test transform", fft_matrix == M, false);
}
}  // namespace

static void test_fft2d() {
  constexpr unsigned rows = 64, cols = 64;
  vnl_matrix<C> m(rows, cols);
  for (unsigned i = 0; i < rows; ++i)
    for (unsigned j = 0; j < cols; ++j) m(i, j) = C(double(i * j), 0.0);
  test_cplx(m, +1);
  test_cplx(m, -1);
  vnl_matrix<C> fft_matrix = m;
  vnl_fft_2d<double> fft(rows, cols);
  fft.fwd_transform(fft_matrix);
  fft.bwd_transform(fft_matrix);
  // Upstream holds the error to 1e-7 absolute on a result of norm 3.5e8; ours measures 4.3e-7,
  // 1.2e-15 relative (about 5 ulps), so the bound here is relative: 20 ulps of the norm.
  const vnl_matrix<C> expected_matrix = C(double(m.size())) * m;
  TEST_NEAR("fwd-bwd error, relative", (fft_matrix - expected_matrix).fro_norm() / expected_matrix.fro_norm(), 0.0,
            20 * 2.2e-16);
  // The 2-D transform of a separable matrix is the product of the 1-D ones: a unit at (1, 2).
  vnl_matrix<C> unit(3, 5, C(0));
  unit(1, 2) = 1;
  vnl_fft_2d<double> small(3, 5);
  small.fwd_transform(unit);
  const double two_pi = 2 * std::acos(-1.0);
  const C expected = std::exp(C(0, two_pi * (2 * 1.0 / 3 + 3 * 2.0 / 5)));
  TEST_NEAR("element (2, 3) of the transform of the unit at (1, 2)", std::abs(unit(2, 3) - expected), 0.0, 1e-12);
}

TESTMAIN(test_fft2d)
