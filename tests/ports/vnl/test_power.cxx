// SPDX-License-Identifier: BSD-3-Clause
// vnl_power as upstream's test_power.cxx: M^0 = I, M^1 = M, M^n by squaring equals repeated
// products, and a negative power is the inverse's power.
#include <string>

#include "testlib/testlib_test.h"
#include "vnl/vnl_power.h"
#include "vnl_test_types.h"

namespace {

template <class T>
struct CheckPower {
  static void run(const std::string& type) {
    const std::string in = " (" + type + ")";
    const T d[] = {T(1), T(1), T(0), T(1)};  // [[1,1],[0,1]]^n = [[1,n],[0,1]]
    const vnl_matrix_fixed<T, 2, 2> shear(d);
    TEST("M^0 = I" + in, vnl_power(shear, 0).is_identity(), true);
    TEST("M^1 = M" + in, vnl_power(shear, 1) == shear, true);
    TEST("M^7 of a shear" + in, vnl_power(shear, 7)(0, 1) == T(7), true);
    TEST("M^-3 of a shear" + in, vnl_power(shear, -3)(0, 1) == T(-3), true);
    const vnl_matrix<T> m = shear.as_matrix();
    TEST("vnl_matrix M^5 = M M M M M" + in, vnl_power(m, 5) == m * m * m * m * m, true);
    TEST("vnl_matrix M^-2" + in, vnl_power(m, -2)(0, 1) == T(-2), true);
  }
};

void test_power() { for_each_test_scalar<CheckPower>(); }

}  // namespace

TESTMAIN(test_power)
