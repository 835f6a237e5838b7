// SPDX-License-Identifier: BSD-3-Clause
// vnl_transpose(M) in products gives the same results as M.transpose() (upstream's
// test_transpose.cxx), for A^T B, A B^T, A^T v and A^T B^T.
#include <string>

#include "testlib/testlib_test.h"
#include "vnl/vnl_transpose.h"
#include "vnl_test_types.h"

namespace {

template <class T>
struct CheckTranspose {
  static void run(const std::string& type) {
    const std::string in = " (" + type + ")";
    vnl_matrix<T> a(3, 2), b(3, 4);
    for (unsigned i = 0; i < 3; ++i) {
      for (unsigned j = 0; j < 2; ++j) a(i, j) = T(int(i * 2 + j) - 2);
      for (unsigned j = 0; j < 4; ++j) b(i, j) = T(int(i + j * j) - 3);
    }
    TEST("vnl_transpose(A) * B is A^T B" + in, vnl_transpose(a) * b == a.transpose() * b, true);
    TEST("A * vnl_transpose(C) is A C^T" + in, b.transpose() * vnl_transpose(a.transpose()) == b.transpose() * a,
         true);
    vnl_vector<T> v(3, T(1));
    TEST("vnl_transpose(A) * v is A^T v" + in, vnl_transpose(a) * v == a.transpose() * v, true);
    TEST("vnl_transpose(A) * vnl_transpose(C) is A^T C^T" + in,
         vnl_transpose(b) * vnl_transpose(a.transpose()) == b.transpose() * a, true);
    const vnl_matrix<T> at = vnl_transpose(a);
    TEST("vnl_transpose converts to the transposed matrix" + in, at == a.transpose(), true);
  }
};

void test_transpose() { for_each_test_scalar<CheckTranspose>(); }

}  // namespace

TESTMAIN(test_transpose)
