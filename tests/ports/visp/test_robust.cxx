// SPDX-License-Identifier: BSD-3-Clause
/// vpRobust: Tukey's weights around the median with the MAD scale (and its floor), Huber's
/// and Cauchy's; upstream's median is the ceil(n/2)-th smallest.
#include <cmath>

#include "real/real.h"
#include "real_tolerance.h"
#include "testlib/testlib_test.h"
#include "visp3/core/vpColVector.h"
#include "visp3/core/vpRobust.h"

// Tolerances at the real's resolution (within_resolution): the MAD is a difference of inputs
// (each rounded to half an ulp) times 1.4826 (rounded too), and Cauchy's weight 1 / (1 + u^2) is
// below 1e-3 here, where the quotient's half-ulp rounding dominates: 2 ulps each.
static void test_robust() {
  vpColVector r(7);
  const double values[] = {0.1, -0.2, 0.0, 0.3, -0.1, 0.2, 25.0};
  for (unsigned int k = 0; k < 7; ++k) r[k] = real(values[k]);
  vpRobust robust;
  robust.setMinMedianAbsoluteDeviation(real(0.01));
  vpColVector w;
  robust.MEstimator(vpRobust::TUKEY, r, w);
  // Median 0.1 (the 4th smallest); |r - 0.1| sorted: 0, 0.1, 0.1, 0.2, 0.2, 0.3, 24.9 -> MAD 0.2.
  TEST_NEAR("MAD = 1.4826 x median of |r - median|", robust.getMedianAbsoluteDeviation(), 1.4826 * 0.2,
            within_resolution(1e-6, 2));
  TEST_NEAR("the median itself weighs 1", w[0], 1, 1e-6);
  TEST_NEAR("Tukey weight of r = 0.3", w[3], std::pow(1 - std::pow(0.2 / (4.6851 * 1.4826 * 0.2), 2), 2), 1e-5);
  TEST_NEAR("the outlier weighs 0", w[6], 0, 0);
  bool inliers = true;
  for (unsigned int k = 0; k < 6; ++k) inliers = inliers && w[k] > real(0.9);
  TEST("inliers weigh more than 0.9", inliers, true);

  robust.MEstimator(vpRobust::HUBER, r, w);
  TEST_NEAR("Huber: inlier 1", w[1], 1, 0);
  TEST_NEAR("Huber: outlier 1.345 sigma / |r - med|", w[6], 1.345 * 1.4826 * 0.2 / 24.9, 1e-5);
  robust.MEstimator(vpRobust::CAUCHY, r, w);
  TEST_NEAR("Cauchy: outlier", w[6], 1 / (1 + std::pow(24.9 / (2.3849 * 1.4826 * 0.2), 2)),
            within_resolution(1e-6, 2));

  vpColVector same(4, real(3));
  robust.setMinMedianAbsoluteDeviation(real(2));
  robust.MEstimator(vpRobust::TUKEY, same, w);
  TEST_NEAR("MAD floor", robust.getMedianAbsoluteDeviation(), 2, 0);
  TEST_NEAR("equal residues all weigh 1", w[0] + w[1] + w[2] + w[3], 4, 0);
}

TESTMAIN(test_robust)
