// SPDX-License-Identifier: BSD-3-Clause
/// The rigid transformation classes: theta u <-> rotation matrix (including near 0, and near pi
/// with axis components near 0), homogeneous matrix composition and inverse, pose vector round
/// trips, skew and cross products.
#include <cmath>

#include "real/real.h"
#include "real_tolerance.h"
#include "testlib/testlib_test.h"
#include "visp3/core/vpHomogeneousMatrix.h"
#include "visp3/core/vpPoseVector.h"
#include "visp3/core/vpRotationMatrix.h"
#include "visp3/core/vpThetaUVector.h"
#include "visp3/core/vpTranslationVector.h"

namespace {

double tu_difference(const vpThetaUVector& a, const vpThetaUVector& b) {
  double worst = 0;
  for (unsigned int k = 0; k < 3; ++k) worst = std::fmax(worst, std::fabs(static_cast<double>(a[k] - b[k])));
  return worst;
}

// Tolerances at the real's resolution (within_resolution). R(theta u) has sines and cosines
// (an ulp each) in products: an entry within 2 ulps, a product R^T R (3 terms) within 8, so a
// rotation within 16. theta u from R takes the axis from the skew part divided by 2 sin theta:
// one ulp there costs theta / (2 sin theta) = 65 ulps at the case nearest pi on that branch
// (theta = 3.118), so 80; nearer pi the axis comes from the diagonal (within 8).
const double kRotation = within_resolution(1e-5, 16);
const double kThetaU = within_resolution(2e-5, 80);

/// How far theta u from R(tu) is from tu. Where pi - theta is under an ulp (the last case, pi -
/// 1.5e-7, rounds to pi - 3.3e-6 in S47.16: 0.2 ulp) R's skew part, sin theta, is below the
/// resolution and its sign is lost: the same rotation about -u by 2 pi - theta is as right.
double tu_round_trip_error(const vpThetaUVector& back, const vpThetaUVector& tu) {
  const double x = static_cast<double>(tu[0]), y = static_cast<double>(tu[1]), z = static_cast<double>(tu[2]);
  const double theta = std::sqrt(x * x + y * y + z * z);
  const double error = tu_difference(back, tu);
  if (M_PI - theta > within_resolution(0, 1)) return error;
  const double scale = -(2 * M_PI - theta) / theta;
  const vpThetaUVector other{real(x * scale), real(y * scale), real(z * scale)};
  return std::fmin(error, tu_difference(back, other));
}

void test_rotations() {
  const double cases[][3] = {{0.2, -0.3, 0.5}, {0, 0, 0}, {1e-4, 2e-4, -1e-4}, {0, 0, 3.1}, {2.0, -1.5, 1.2},
                             {0, 3.14, 0}, {1.8, 1.8, 1.8}, {3.1415, 0, 0}, {1.884955, -2.513274, 0}};
  for (const auto& v : cases) {
    const vpThetaUVector tu{real(v[0]), real(v[1]), real(v[2])};
    const vpRotationMatrix R(tu);
    TEST("R(theta u) is a rotation", R.isARotationMatrix(real(kRotation)), true);
    TEST_NEAR("theta u of R(theta u) is theta u", tu_round_trip_error(vpThetaUVector(R), tu), 0, kThetaU);
  }
  const vpRotationMatrix Rz(real(0), real(0), real(M_PI / 2));
  TEST_NEAR("quarter turn about z: R[0][1] = -1", Rz[0][1], -1, within_resolution(1e-6, 2));
  TEST_NEAR("quarter turn about z: R[1][0] = 1", Rz[1][0], 1, within_resolution(1e-6, 2));
  const vpTranslationVector x(1, 0, 0);
  TEST_NEAR("quarter turn about z maps x to y", (Rz * x)[1], 1, within_resolution(1e-6, 2));
  TEST_NEAR("R R^T is the identity", (Rz * Rz.inverse())[0][0], 1, within_resolution(1e-6, 4));

  vpThetaUVector tu(real(0), real(0.6), real(0.8));
  real theta;
  vpColVector u;
  tu.extract(theta, u);
  TEST_NEAR("theta is the norm", theta, 1, 1e-6);
  TEST_NEAR("u is the unit axis", u[2], 0.8, within_resolution(1e-6, 2));
}

void test_homogeneous() {
  const vpHomogeneousMatrix M(real(0.1), real(-0.2), real(0.5), real(0.3), real(-0.1), real(0.2));
  TEST("M is homogeneous", M.isAnHomogeneousMatrix(real(kRotation)), true);
  const vpHomogeneousMatrix I = M * M.inverse();
  double worst = 0;
  for (unsigned int r = 0; r < 4; ++r)
    for (unsigned int c = 0; c < 4; ++c)
      worst = std::fmax(worst, std::fabs(static_cast<double>(I[r][c]) - (r == c ? 1.0 : 0.0)));
  TEST_NEAR("M M^-1 = I", worst, 0, within_resolution(1e-5, 8));
  const vpTranslationVector p(1, 2, 3);
  const vpTranslationVector q = M.inverse() * (M * p);
  TEST_NEAR("M^-1 (M p) = p", (q - p).frobeniusNorm(), 0, 1e-5);
  vpColVector h(4);
  h[0] = 1;
  h[1] = 2;
  h[2] = 3;
  h[3] = 1;
  TEST_NEAR("M times a homogeneous point", (M * h)[2], (M * p)[2], 1e-6);

  const vpPoseVector pose(M);
  const vpHomogeneousMatrix back(pose);
  TEST_NEAR("pose vector keeps the translation", pose[2], 0.5, 1e-6);
  TEST_NEAR("pose vector keeps theta u", pose[3], 0.3, 1e-5);
  TEST_NEAR("homogeneous matrix from its pose vector", back[1][2], M[1][2], 1e-5);
  const vpPoseVector from_parts(M.getTranslationVector(), M.getRotationMatrix());
  TEST_NEAR("pose vector from t and R", from_parts[5], 0.2, 1e-5);
  vpRotationMatrix R;
  vpTranslationVector t;
  M.extract(R);
  M.extract(t);
  TEST_NEAR("extract translation", t[1], M[1][3], 0);
  TEST_NEAR("extract rotation", R[0][1], M[0][1], 0);
}

void test_translation() {
  const vpTranslationVector a(1, 0, 0), b(0, 1, 0);
  const vpTranslationVector c = vpTranslationVector::cross(a, b);
  TEST_NEAR("x cross y = z", c[2], 1, 0);
  const vpMatrix S = a.skew();
  vpColVector bv = b;
  TEST_NEAR("[a]x b = a cross b", (S * bv)[2], 1, 0);
  TEST_NEAR("norm", vpTranslationVector(3, 4, 0).frobeniusNorm(), 5, 1e-6);
  TEST_NEAR("negation and scaling", (-(a * real(2)))[0], -2, 0);
}

}  // namespace

static void test_transformations() {
  test_rotations();
  test_homogeneous();
  test_translation();
}

TESTMAIN(test_transformations)
