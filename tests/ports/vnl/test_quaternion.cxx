// SPDX-License-Identifier: BSD-3-Clause
// vnl_quaternion behaves as upstream's test_quaternion.cxx checks: storage order, products,
// rotation of points, matrix and Euler-angle round trips, inverse and conjugate.
#include <cmath>
#include <string>

#include "testlib/testlib_test.h"
#include "vnl/vnl_math.h"
#include "vnl/vnl_quaternion.h"
#include "vnl/vnl_random.h"
#include "vnl_test_types.h"

namespace {

template <class T>
struct CheckQuaternion {
  static void run(const std::string& type) {
    const std::string in = " (" + type + ")";
    const double tol = ulps<T>(256) + 1e-14;
    const vnl_quaternion<T> q(T(1), T(2), T(3), T(4));
    TEST_NEAR(".x() is the first imaginary part" + in, q.x(), 1.0, 0.0);
    TEST_NEAR(".y()" + in, q.y(), 2.0, 0.0);
    TEST_NEAR(".z()" + in, q.z(), 3.0, 0.0);
    TEST_NEAR(".r() is the real part, stored last" + in, q.r(), 4.0, 0.0);
    TEST_NEAR("q[3] is r" + in, q[3], 4.0, 0.0);
    TEST("== compares all four" + in, q == vnl_quaternion<T>(T(1), T(2), T(3), T(4)), true);
    TEST("!= sees one difference" + in, q != vnl_quaternion<T>(T(1), T(2), T(3), T(5)), true);

    // A quarter turn about z: x -> y, y -> -x.
    const vnl_vector_fixed<T, 3> z_axis(T(0), T(0), T(1));
    const vnl_quaternion<T> quarter(z_axis, vnl_math::pi_over_2);
    const vnl_vector_fixed<T, 3> px(T(1), T(0), T(0));
    const vnl_vector_fixed<T, 3> turned = quarter.rotate(px);
    TEST_NEAR("rotate (1,0,0) a quarter turn about z: x" + in, turned[0], 0.0, tol);
    TEST_NEAR("rotate (1,0,0) a quarter turn about z: y" + in, turned[1], 1.0, tol);
    TEST_NEAR("angle() of the quarter turn" + in, quarter.angle(), vnl_math::pi_over_2, tol);
    TEST_NEAR("axis() of the quarter turn is z" + in, quarter.axis()[2], 1.0, tol);
    TEST_NEAR("axis of the identity is (0,0,1) by convention" + in, vnl_quaternion<T>().axis()[2], 1.0, 0.0);

    // rotate(v) equals R v with R the transpose of rotation_matrix_transpose().
    const vnl_vector_fixed<T, 3> axis = vnl_vector_fixed<T, 3>(T(1), T(-2), T(2)) / T(3);
    const vnl_quaternion<T> q1(axis, 0.7);
    const vnl_vector_fixed<T, 3> p(T(0.3), T(-1.2), T(2.5));
    const vnl_matrix_fixed<T, 3, 3> R = q1.rotation_matrix_transpose().transpose();
    TEST_NEAR("rotate(p) is R p" + in, (q1.rotate(p) - R * p).inf_norm(), 0.0, 4 * tol);
    TEST_NEAR("rotation keeps length" + in, q1.rotate(p).two_norm(), p.two_norm(), 4 * tol);
    const vnl_quaternion<T> back(q1.rotation_matrix_transpose());
    TEST_NEAR("quaternion from its own matrix transpose" + in, (back - q1).inf_norm(), 0.0, 4 * tol);
    TEST_NEAR("rotation_matrix_transpose_4 holds the 3x3 block" + in,
              q1.rotation_matrix_transpose_4()(1, 2) - q1.rotation_matrix_transpose()(1, 2), 0.0, 0.0);
    TEST_NEAR("rotation_matrix_transpose_4 (3,3) is 1" + in, q1.rotation_matrix_transpose_4()(3, 3), 1.0, 0.0);

    // Products compose rotations: (q2 * q1) rotates by q1 then q2.
    const vnl_quaternion<T> q2(vnl_vector_fixed<T, 3>(T(0), T(1), T(0)), -0.4);
    TEST_NEAR("(q2 * q1).rotate(p) is q2.rotate(q1.rotate(p))" + in,
              ((q2 * q1).rotate(p) - q2.rotate(q1.rotate(p))).inf_norm(), 0.0, 8 * tol);
    const vnl_quaternion<T> unit = q1 * q1.inverse();
    TEST_NEAR("q * q.inverse() is the identity (real part)" + in, unit.r(), 1.0, tol);
    TEST_NEAR("q * q.inverse() is the identity (imaginary)" + in, unit.imaginary().inf_norm(), 0.0, tol);
    TEST_NEAR("conjugate negates the imaginary part" + in, q.conjugate().y(), -2.0, 0.0);
    TEST_NEAR("inverse of (1,2,3,4) is conjugate / 30" + in, q.inverse().r(), 4.0 / 30, ulps<T>(16));

    // Euler angles round trip.
    vnl_random rng(1234);
    bool euler_ok = true;
    for (int trial = 0; trial < 20; ++trial) {
      const T ax = T(rng.drand64(-1.5, 1.5)), ay = T(rng.drand64(-1.4, 1.4)), az = T(rng.drand64(-3.0, 3.0));
      const vnl_quaternion<T> e(ax, ay, az);
      const vnl_vector_fixed<T, 3> angles = e.rotation_euler_angles();
      const double worst = std::fmax(std::fabs(static_cast<double>(angles[0] - ax)),
                                     std::fmax(std::fabs(static_cast<double>(angles[1] - ay)),
                                               std::fabs(static_cast<double>(angles[2] - az))));
      if (worst > 64 * tol) euler_ok = false;
    }
    TEST("20 random Euler angles -> quaternion -> Euler angles agree" + in, euler_ok, true);
    const vnl_quaternion<T> about_x(T(0.5), T(0), T(0));
    TEST_NEAR("Euler (0.5, 0, 0) is 0.5 rad about x" + in, about_x.angle(), 0.5, 4 * tol);
    TEST_NEAR("Euler (0.5, 0, 0) has axis x" + in, about_x.axis()[0], 1.0, 4 * tol);
  }
};

void test_quaternion() { for_each_test_scalar<CheckQuaternion>(); }

}  // namespace

TESTMAIN(test_quaternion)
