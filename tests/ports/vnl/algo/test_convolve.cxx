// SPDX-License-Identifier: BSD-3-Clause
// vnl_convolve as upstream's algo test_convolve.cxx: small exact convolutions in int and
// double, commutativity, the FFT path at several lengths against the direct one (here on
// 1000 x 200 random values, without upstream's timings), and the cyclic convolution.
#include "testlib/testlib_test.h"
#include "vnl/algo/vnl_convolve.h"
#include "vnl/vnl_double_2.h"
#include "vnl/vnl_int_2.h"
#include "vnl/vnl_random.h"

static void test_convolve() {
  int b_data[] = {-2, 0, 4, 6, 2, 0};
  const vnl_vector<int> b(6, 6, b_data);
  const vnl_vector<double> k1 = vnl_double_2(0.5, -0.5).as_vector();
  const vnl_vector<double> r1 = vnl_convolve(b, k1, static_cast<double*>(nullptr));
  TEST("vnl_convolve() simple length", r1.size(), 7u);
  TEST("vnl_convolve() simple values", r1[0] == -1 && r1[1] == 1 && r1[2] == 2 && r1[3] == 1 && r1[4] == -2 &&
                                           r1[5] == -1 && r1[6] == 0,
       true);
  const vnl_vector<int> k2 = vnl_int_2(1, -1).as_vector();
  const vnl_vector<int> r2 = vnl_convolve(b, k2);
  TEST("vnl_convolve() simple length", r2.size(), 7u);
  TEST("vnl_convolve() simple values", r2[0] == -2 && r2[1] == 2 && r2[2] == 4 && r2[3] == 2 && r2[4] == -4 &&
                                           r2[5] == -2 && r2[6] == 0,
       true);
  TEST("vnl_convolve() 2nd form", vnl_convolve(b, k2, static_cast<int*>(nullptr)) == r2, true);
  TEST("vnl_convolve() commutativity", vnl_convolve(k2, b) == r2, true);
  TEST_NEAR("vnl_convolve() with_fft(7)", (vnl_convolve(b, k1, static_cast<double*>(nullptr), 1) - r1).two_norm(), 0.0,
            1e-6);
  TEST_NEAR("vnl_convolve() with_fft(8)", (vnl_convolve(b, k1, static_cast<double*>(nullptr), 8) - r1).two_norm(), 0.0,
            1e-6);

  vnl_vector<double> l(1000), k3(200);
  vnl_random rng(1234);
  for (double& x : l) x = rng.drand64(-1, 1);
  for (double& x : k3) x = rng.drand64(-1, 1);
  const vnl_vector<double> direct = vnl_convolve(l, k3);
  TEST("the full convolution has n1 + n2 - 1 values", direct.size(), 1199u);
  TEST_NEAR("vnl_convolve() with_fft(2048), powers of 2", (direct - vnl_convolve(l, k3, 2048)).two_norm(), 0.0, 1e-6);
  TEST_NEAR("vnl_convolve() with_fft(1280), 2 and 5", (direct - vnl_convolve(l, k3, 1280)).two_norm(), 0.0, 1e-6);
  TEST_NEAR("vnl_convolve() with_fft(1296), 2 and 3", (direct - vnl_convolve(l, k3, 1296)).two_norm(), 0.0, 1e-6);
  TEST_NEAR("vnl_convolve() with_fft(1201) rounds the length up to 1215", (direct - vnl_convolve(l, k3, 1201)).two_norm(),
            0.0, 1e-6);

  double c1_data[] = {-1, 0, 1, 2, 3, 4};
  const vnl_vector<double> c1(6, 6, c1_data);
  double c2_data[] = {5, 3, 1, -1, -3, -5};
  const vnl_vector<double> c2(6, 6, c2_data);
  const vnl_vector<double> r5 = vnl_convolve_cyclic(c1, c2, static_cast<double*>(nullptr));
  TEST("vnl_convolve_cyclic() length", r5.size(), 6u);
  TEST("vnl_convolve_cyclic() values",
       r5[0] == 5 && r5[1] == -13 && r5[2] == -19 && r5[3] == -13 && r5[4] == 5 && r5[5] == 35, true);
  TEST_NEAR("vnl_convolve_cyclic() with_fft",
            (vnl_convolve_cyclic(c1, c2, static_cast<double*>(nullptr), true) - r5).two_norm(), 0.0, 1e-6);
}

TESTMAIN(test_convolve)
