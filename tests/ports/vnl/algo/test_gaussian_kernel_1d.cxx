// SPDX-License-Identifier: BSD-3-Clause
// vnl_gaussian_kernel_1d (upstream has no test of its own): the half kernel sums to 0.5, falls
// off as exp(-x^2 / 2 sigma^2) and reaches to where the density drops below the cutoff.
#include <cmath>

#include "testlib/testlib_test.h"
#include "vnl/algo/vnl_gaussian_kernel_1d.h"

static void test_gaussian_kernel_1d() {
  const double sigma = 2.0;
  const vnl_gaussian_kernel_1d kernel(sigma);
  double sum = 0;
  for (int i = 0; i < kernel.width(); ++i) sum += kernel[i];
  TEST_NEAR("the half kernel sums to 0.5", sum, 0.5, 1e-12);
  TEST_NEAR("its ratios follow the Gaussian", kernel[3] / kernel[0], std::exp(-9 / (2 * sigma * sigma)), 1e-12);
  TEST_NEAR("G(x) = exp(-x^2 / 2 sigma^2)", kernel.G(2), std::exp(-0.5), 1e-15);
  // Density below 0.5/256 from x = sigma sqrt(-2 ln(cutoff sigma sqrt(2 pi))) = 6.08: 7 samples.
  TEST("width reaches the cutoff", kernel.width(), 7);
  TEST("a wider sigma gives a wider kernel", vnl_gaussian_kernel_1d(4.0).width() > kernel.width(), true);
}

TESTMAIN(test_gaussian_kernel_1d)
