// SPDX-License-Identifier: BSD-3-Clause
// The rotation helpers: Rodrigues' formula gives proper rotations about the right axis by the
// right angle, thetaU inverts it over (0, pi] including tiny angles in fixed point, hat and vee
// are inverse, and the exp coefficients match their closed forms.
#include <cmath>
#include <string>

#include "testlib/testlib_test.h"
#include "vnl/vnl_rotation_matrix.h"
#include "vnl/vnl_rotation_matrix.hxx"
#include "vnl_test_types.h"

namespace {

template <class T>
vnl_vector_fixed<T, 3> rotation_vector(double theta, double x, double y, double z) {
  const double norm = std::sqrt(x * x + y * y + z * z);
  return vnl_vector_fixed<T, 3>(T(theta * x / norm), T(theta * y / norm), T(theta * z / norm));
}

template <class T>
struct CheckRotation {
  static void run(const std::string& type) {
    const std::string in = " (" + type + ")";
    const double tol = ulps<T>(64);

    const vnl_vector_fixed<T, 3> w(T(0.3), T(-0.2), T(0.5));
    const vnl_vector_fixed<T, 3> p(T(1), T(2), T(-1));
    const vnl_vector_fixed<T, 3> hp = vnl_rotation_hat(w) * p;
    const vnl_vector_fixed<T, 3> wxp = vnl_cross_3d(w, p);
    TEST_NEAR("hat(w) * p is w x p" + in, (hp - wxp).inf_norm(), 0.0, tol);
    TEST("vee(hat(w)) is w" + in, vnl_rotation_vee(vnl_rotation_hat(w)) == w, true);

    TEST("exp(0) is the identity" + in, vnl_rotation_matrix(vnl_vector_fixed<T, 3>()).is_identity(T(0)), true);
    const vnl_matrix_fixed<T, 3, 3> quarter = vnl_rotation_matrix(rotation_vector<T>(std::acos(-1.0) / 2, 0, 0, 1));
    const vnl_vector_fixed<T, 3> ex(T(1), T(0), T(0));
    TEST_NEAR("a quarter turn about z maps x to y" + in, (quarter * ex)[1], 1.0, tol);
    TEST_NEAR("a quarter turn about z leaves no x" + in, (quarter * ex)[0], 0.0, tol);

    const double angles[] = {1e-5, 3e-4, 1e-2, 0.3, 1.0, 1.6, 2.2, 2.9, 3.1, 3.14};
    for (double theta : angles) {
      const std::string at = " at theta=" + std::to_string(theta) + in;
      const vnl_vector_fixed<T, 3> v = rotation_vector<T>(theta, 0.3, -0.5, 0.8);
      const vnl_matrix_fixed<T, 3, 3> R = vnl_rotation_matrix(v);
      TEST("R^T R is the identity" + at, (R.transpose() * R).is_identity(T(tol)), true);
      TEST_NEAR("R leaves its axis fixed" + at, (R * v - v).inf_norm(), 0.0, tol);
      const T trace = R(0, 0) + R(1, 1) + R(2, 2);
      TEST_NEAR("trace(R) is 1 + 2 cos(theta)" + at, trace, 1 + 2 * std::cos(theta), 2 * tol);
      const vnl_vector_fixed<T, 3> back = vnl_rotation_thetau(R);
      // Near pi the angle is ill-conditioned through the trace, so the tolerance grows there.
      const double log_tol = theta > 3.0 ? 16 * tol : 2 * tol;
      TEST_NEAR("thetau(exp(w)) is w" + at, (back - v).inf_norm(), 0.0, log_tol);
    }

    // Tiny rotation vectors: their squares underflow in fixed point, the scaled norm does not.
    const vnl_vector_fixed<T, 3> tiny(T(3e-5), T(-2e-5), T(1e-5));
    const vnl_matrix_fixed<T, 3, 3> Rt = vnl_rotation_matrix(tiny);
    // vee(R) = w sin(theta)/theta, which differs from w by 1e-14 here.
    TEST_NEAR("exp of a tiny w has w as its antisymmetric part" + in, (vnl_rotation_vee(Rt) - tiny).inf_norm(), 0.0,
              ulps<T>(4) + 1e-14);
    TEST_NEAR("thetau of exp of a tiny w is w" + in, (vnl_rotation_thetau(Rt) - tiny).inf_norm(), 0.0, ulps<T>(4));

    for (double theta : {0.0, 1e-3, 0.5, 1.2, 2.5}) {
      const std::string at = " at theta=" + std::to_string(theta) + in;
      const vnl_rotation_coefficients<T> k = vnl_rotation_exp_coefficients(rotation_vector<T>(theta, 1, 2, 3));
      const double a = theta == 0 ? 1 : std::sin(theta) / theta;
      const double half_sinc = theta == 0 ? 1 : std::sin(theta / 2) / (theta / 2);
      const double b = half_sinc * half_sinc / 2;  // (1-cos)/theta^2 without cancellation
      const double c = theta == 0 ? 1.0 / 6 : (theta - std::sin(theta)) / (theta * theta * theta);
      TEST_NEAR("coefficient a = sin(theta)/theta" + at, k.a, a, tol);
      TEST_NEAR("coefficient b = (1-cos(theta))/theta^2" + at, k.b, b, tol);
      // c's closed form itself cancels in double below 1e-3; 1e-9 is its own accuracy there.
      TEST_NEAR("coefficient c = (theta-sin(theta))/theta^3" + at, k.c, c, theta < 2e-3 ? 1e-9 + tol : tol);
    }
  }
};

void test_rotation_matrix() { for_each_test_scalar<CheckRotation>(); }

}  // namespace

TESTMAIN(test_rotation_matrix)
