// SPDX-License-Identifier: BSD-3-Clause
// vnl_sym_matrix as upstream's test_sym_matrix.cxx: one element for (i, j) and (j, i), packed
// rows, conversion to and from vnl_matrix, comparison, swap, update and set_half_row.
#include <string>

#include "testlib/testlib_test.h"
#include "vnl/vnl_sym_matrix.h"
#include "vnl_test_types.h"

namespace {

template <class T>
struct CheckSym {
  static void run(const std::string& type) {
    const std::string in = " (" + type + ")";
    vnl_sym_matrix<T> m1(3);
    TEST("vnl_sym_matrix m1(3) stores 6 values" + in, m1.size() == 6u && m1.rows() == 3u, true);
    m1(0, 2) = T(5);
    TEST("(0,2) and (2,0) are one element" + in, m1(2, 0) == T(5) && m1.fast(2, 0) == T(5), true);
    const T packed[] = {T(1), T(2), T(3), T(4), T(5), T(6)};  // rows (1), (2 3), (4 5 6)
    const vnl_sym_matrix<T> sm3(packed, 3);
    TEST("(const vnl_sym_matrix) sm3 row 2" + in, sm3[2][1] == T(5) && sm3(1, 2) == T(5), true);
    const vnl_matrix<T> ma2 = sm3.as_matrix();
    TEST("(const vnl_matrix) ma2 is symmetric" + in, is_symmetric(ma2) && ma2(0, 1) == T(2), true);
    TEST("operator== with a vnl_matrix" + in, sm3 == ma2 && ma2 == sm3, true);
    TEST("from a vnl_matrix" + in, vnl_sym_matrix<T>(ma2) == sm3, true);
    vnl_sym_matrix<T> a(2, T(1)), b(3, T(2));
    a.swap(b);
    TEST("swap" + in, a.rows() == 3u && b.rows() == 2u && a(2, 2) == T(2), true);
    a.update(b, 1);
    TEST("update writes the block at (1,1)" + in, a(2, 1) == T(1) && a(0, 1) == T(2), true);
    vnl_sym_matrix<T> c;
    c = sm3;
    TEST("operator =" + in, c == sm3, true);
    c.set_half_row(vnl_vector<T>(3, T(9)), 2);
    TEST("set_half_row" + in, c(0, 2) == T(9) && c(2, 2) == T(9) && c != sm3, true);
    TEST("get_half_row" + in, c.get_half_row(1)[1] == T(3), true);
    c *= T(2);
    TEST("*= scales" + in, c(1, 1) == T(6), true);
  }
};

void test_sym_matrix() {
  CheckSym<int>::run("int");
  for_each_test_scalar<CheckSym>();
}

}  // namespace

TESTMAIN(test_sym_matrix)
