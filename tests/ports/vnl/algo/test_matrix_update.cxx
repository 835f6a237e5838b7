// SPDX-License-Identifier: BSD-3-Clause
// vnl_matrix_update as upstream's algo test_matrix_update.cxx: M += a b^T equals adding the
// outer product.
#include <string>

#include "algo_test_support.h"
#include "testlib/testlib_test.h"
#include "vnl/algo/vnl_matrix_update.h"

namespace {

template <class T>
struct CheckUpdate {
  static void run(const std::string& type) {
    const std::string in = " (" + type + ")";
    vnl_matrix<T> m = random_matrix<T>(3, 4, 1);
    const vnl_matrix<T> original(m);
    const vnl_vector<T> a{T(1), T(-2), T(0.5)}, b{T(2), T(0), T(1), T(-1)};
    vnl_matrix_update(m, a, b);
    TEST_NEAR("M + a b^T" + in, distance(m, original + outer_product(a, b)), 0.0, decomposition_tol<T>(8));
  }
};

void test_matrix_update() { for_each_test_scalar<CheckUpdate>(); }

}  // namespace

TESTMAIN(test_matrix_update)
