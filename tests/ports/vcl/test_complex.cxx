// SPDX-License-Identifier: BSD-3-Clause
// vcl_complex.h gives std::complex with its functions (upstream's test_complex).
#include "testlib/testlib_test.h"
#include "vcl_complex.h"

static void test_complex() {
  const std::complex<double> z(3.0, 4.0);
  TEST_NEAR("abs(3+4i) is 5", std::abs(z), 5.0, 1e-15);
  TEST_NEAR("norm(3+4i) is 25", std::norm(z), 25.0, 1e-15);
  TEST("conj(3+4i) is 3-4i", std::conj(z), std::complex<double>(3.0, -4.0));
  TEST_NEAR("polar(2, pi/2) is 2i", std::polar(2.0, std::acos(-1.0) / 2), std::complex<double>(0.0, 2.0), 1e-15);
  TEST_NEAR("sqrt(-4) is 2i", std::sqrt(std::complex<double>(-4.0, 0.0)), std::complex<double>(0.0, 2.0), 1e-15);
  const std::complex<float> f(1.0f, -1.0f);
  TEST_NEAR("complex<float> product (1-i)(1-i) is -2i", f * f, std::complex<double>(0.0, -2.0), 1e-6);
}

TESTMAIN(test_complex)
