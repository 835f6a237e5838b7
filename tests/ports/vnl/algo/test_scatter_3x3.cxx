// SPDX-License-Identifier: BSD-3-Clause
// vnl_scatter_3x3 (upstream has no test of its own): the scatter of points on a plane has the
// plane's normal as its minimum eigenvector, outer products add and subtract, and an asymmetric
// sum is symmetrised by force_symmetric.
#include <cmath>
#include <string>

#include "testlib/testlib_test.h"
#include "vnl/algo/vnl_scatter_3x3.h"

namespace {
template <class T>
void check(const char* type, double tol) {
  const std::string in = std::string(" (") + type + ")";
  vnl_scatter_3x3<T> S;
  TEST("starts at zero" + in, S.fro_norm() == T(0), true);
  // Points on the plane x + 2 y + 2 z = 0, normal (1, 2, 2) / 3.
  const T points[5][3] = {{2, -1, 0}, {0, 1, -1}, {2, 0, -1}, {-2, 2, -1}, {4, -1, -1}};
  for (const auto& p : points) S.add_outer_product(vnl_vector_fixed<T, 3>(p[0], p[1], p[2]));
  const vnl_vector_fixed<T, 3> n = S.minimum_eigenvector();
  const double sign = n[0] < 0 ? -1 : 1;
  TEST_NEAR("the minimum eigenvector is the plane's normal (x)" + in, sign * n[0], 1.0 / 3, tol);
  TEST_NEAR("the minimum eigenvector is the plane's normal (y)" + in, sign * n[1], 2.0 / 3, tol);
  TEST_NEAR("the minimum eigenvector is the plane's normal (z)" + in, sign * n[2], 2.0 / 3, tol);
  TEST("V() holds it as its first column" + in, S.V()(0, 0) == n[0], true);
  vnl_scatter_3x3<T> A = S;
  A.sub_outer_product(vnl_vector_fixed<T, 3>(points[0][0], points[0][1], points[0][2]));
  TEST_NEAR("sub_outer_product takes back v v^T" + in, A(0, 0), double(S(0, 0)) - 4, tol);
  vnl_scatter_3x3<T> B;
  B.add_outer_product(vnl_vector_fixed<T, 3>(1, 0, 0), vnl_vector_fixed<T, 3>(0, 1, 0));
  TEST("add_outer_product(u, v) adds v u^T" + in, B(1, 0) == T(1) && B(0, 1) == T(0), true);
  B.force_symmetric();
  TEST("force_symmetric averages the two halves" + in, B(1, 0) == T(0.5) && B(0, 1) == T(0.5), true);
}
}  // namespace

static void test_scatter_3x3() {
  check<double>("double", 1e-12);
  check<float>("float", 1e-5);
}

TESTMAIN(test_scatter_3x3)
