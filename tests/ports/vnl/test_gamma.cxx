// SPDX-License-Identifier: BSD-3-Clause
// vnl_gamma, vnl_gamma_p/q, vnl_erf/erfc, vnl_digamma and vnl_beta at the values upstream's
// test_gamma.cxx checks (known values of the functions).
#include <cmath>

#include "testlib/testlib_test.h"
#include "vnl/vnl_beta.h"
#include "vnl/vnl_erf.h"
#include "vnl/vnl_gamma.h"

static void test_gamma() {
  TEST_NEAR("vnl_log_gamma(1)", vnl_log_gamma(1), 0, 1e-12);
  TEST_NEAR("vnl_gamma(1)", vnl_gamma(1), 1, 1e-12);
  TEST_NEAR("vnl_gamma(0.5) = sqrt(pi)", vnl_gamma(0.5), 1.7724538509055160, 1e-12);
  TEST_NEAR("vnl_gamma(1.5)", vnl_gamma(1.5), 0.88622692545275801, 1e-12);
  TEST_NEAR_REL("vnl_gamma(10.7)", vnl_gamma(10.7), 1799844.07893, 1e-10);
  TEST_NEAR("vnl_gamma_p(2,0)", vnl_gamma_p(2, 0), 0, 1e-12);
  TEST_NEAR("vnl_gamma_p(2,inf)", vnl_gamma_p(2, 1e9), 1.0, 1e-12);
  TEST_NEAR("vnl_gamma_p(2.5,1.5)", vnl_gamma_p(2.5, 1.5), 0.300014164, 1e-8);
  TEST_NEAR("vnl_gamma_p(2.5,0.5)", vnl_gamma_p(2.5, 0.5), 0.037434227, 1e-8);
  TEST_NEAR("vnl_gamma_p(10,10)", vnl_gamma_p(10, 10), 0.542070286, 1e-8);
  TEST_NEAR("vnl_gamma_q(2,0)", vnl_gamma_q(2, 0), 1.0, 1e-12);
  TEST_NEAR("vnl_gamma_q(2,inf)", vnl_gamma_q(2, 1e9), 0, 1e-12);
  TEST_NEAR("P + Q = 1 at (3, 7)", vnl_gamma_p(3, 7) + vnl_gamma_q(3, 7), 1.0, 1e-14);
  TEST_NEAR("vnl_cum_prob_chi2(2, 2) = 1 - exp(-1)", vnl_cum_prob_chi2(2, 2), 1 - std::exp(-1.0), 1e-14);
  TEST_NEAR("vnl_erf(0)", vnl_erf(0), 0, 1e-15);
  TEST_NEAR("vnl_erf(inf)", vnl_erf(1e9), 1.0, 1e-15);
  TEST_NEAR("vnl_erf(-inf)", vnl_erf(-1e9), -1.0, 1e-15);
  TEST("vnl_erfc(0)", vnl_erfc(0.0), 1.0);
  TEST_NEAR("vnl_erfc(1.2) = 1-vnl_erf(1.2)", vnl_erfc(1.2), 1.0 - vnl_erf(1.2), 1e-15);
  TEST_NEAR("vnl_erfc(2)", vnl_erfc(2), 0.00467773498105, 1e-14);
  TEST_NEAR_REL("vnl_erfc(6)", vnl_erfc(6), 2.15197367125e-17, 1e-10);
  TEST_NEAR("vnl_scaled_erfc(6) within 0.01 of exp(36) erfc(6) (upstream's asymptote)", vnl_scaled_erfc(6),
            std::exp(36.0) * 2.15197367125e-17, 0.01);
  TEST_NEAR_REL("vnl_scaled_erfc(30) is 1/(30 sqrt(pi))", vnl_scaled_erfc(30.0), 1 / (30 * std::sqrt(3.14159265358979323846)), 1e-15);
  TEST_NEAR("vnl_scaled_erfc(-1e9) is about 0, as upstream", vnl_scaled_erfc(-1e9), 0.0, 1e-8);
  TEST_NEAR("vnl_digamma(1) = -Euler's gamma", vnl_digamma(1), -0.57721566490153286, 1e-14);
  TEST_NEAR("vnl_digamma(0.5)", vnl_digamma(0.5), -1.9635100260214235, 1e-14);
  TEST_NEAR("vnl_beta(2, 3) = 1/12", vnl_beta(2.0, 3.0), 1.0 / 12, 1e-15);
  TEST_NEAR("vnl_log_beta(0.5, 0.5) = log(pi)", vnl_log_beta(0.5, 0.5), std::log(3.14159265358979323846), 1e-14);
}

TESTMAIN(test_gamma)
