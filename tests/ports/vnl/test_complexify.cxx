// SPDX-License-Identifier: BSD-3-Clause
// vnl_complexify, vnl_real and vnl_imag as upstream's test_complexify.cxx: real and imaginary
// parts go in and come back out, for arrays, vectors and matrices, fixed and not.
#include <complex>

#include "testlib/testlib_test.h"
#include "vnl/vnl_complexify.h"
#include "vnl/vnl_imag.h"
#include "vnl/vnl_real.h"

static void test_complexify() {
  const vnl_vector<double> re{1, 2, 3}, im{-1, 0, 4};
  const vnl_vector<std::complex<double>> c = vnl_complexify(re, im);
  TEST("complexify(re, im)", c[2], std::complex<double>(3, 4));
  TEST("vnl_real", vnl_real(c) == re, true);
  TEST("vnl_imag", vnl_imag(c) == im, true);
  TEST("complexify(re) has zero imaginary part", vnl_imag(vnl_complexify(re)).is_zero(), true);
  const vnl_vector_fixed<float, 2> f(1.5f, -2.0f);
  TEST("fixed vector", vnl_complexify(f)[1], std::complex<float>(-2.0f, 0.0f));
  const vnl_matrix<double> m{{1, 2}, {3, 4}};
  const vnl_matrix<std::complex<double>> cm = vnl_complexify(m, m * 2.0);
  TEST("matrix", cm(1, 0), std::complex<double>(3, 6));
  TEST("vnl_real of a matrix", vnl_real(cm) == m, true);
  vnl_matrix_fixed<double, 2, 2> mf(m);
  TEST("fixed matrix", vnl_imag(vnl_complexify(mf))(1, 1), 0.0);
}

TESTMAIN(test_complexify)
