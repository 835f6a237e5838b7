// SPDX-License-Identifier: BSD-3-Clause
// vnl_matrix_fixed_ref as upstream's test_matrix_fixed_ref.cxx: a view of a fixed matrix or a
// raw block reads and writes it, row and column setters, arithmetic and products, and the
// const view.
#include <string>

#include "testlib/testlib_test.h"
#include "vnl/vnl_matrix_fixed_ref.h"
#include "vnl_test_types.h"

namespace {

template <class T>
struct CheckMatrixFixedRef {
  static void run(const std::string& type) {
    const std::string in = " (" + type + ")";
    vnl_matrix_fixed<T, 2, 3> m;
    const vnl_matrix_fixed_ref<T, 2, 3> ref(m);
    ref(1, 2) = T(5);
    TEST("writing through the view changes the matrix" + in, m(1, 2) == T(5), true);
    ref.set_row(0, vnl_vector_fixed<T, 3>(T(1), T(2), T(3)));
    TEST("set_row writes the matrix's row" + in, m(0, 1) == T(2), true);
    ref.set_column(0, vnl_vector_fixed<T, 2>(T(-1), T(4)));
    TEST("set_column writes the matrix's column" + in, m(1, 0) == T(4) && m(0, 0) == T(-1), true);
    ref *= T(2);
    TEST("*= scales the matrix" + in, m(1, 2) == T(10), true);
    const vnl_matrix_fixed_ref_const<T, 2, 3> cref(m);
    TEST("const view get_row" + in, cref.get_row(0)[2] == T(6), true);
    TEST("const view get_column" + in, cref.get_column(2)[1] == T(10), true);
    TEST("const view transpose" + in, cref.transpose()(2, 1) == T(10), true);
    T block[9];
    const vnl_matrix_fixed_ref<T, 3, 3> square(block);
    square.set_identity();
    TEST("a view of a raw block: set_identity" + in, block[4] == T(1) && block[1] == T(0), true);
    square(0, 2) = T(3);
    square.inplace_transpose();
    TEST("inplace_transpose of the block" + in, block[6] == T(3) && block[2] == T(0), true);
    const vnl_matrix_fixed<T, 2, 3> product = cref * vnl_matrix_fixed_ref_const<T, 3, 3>(block);
    TEST("product of views: column 2 is unchanged" + in, product(0, 2) == m(0, 2) && product(1, 2) == m(1, 2), true);
    TEST("product of views: column 0 picks up 3 x column 2" + in,
         product(0, 0) == m(0, 0) + T(3) * m(0, 2) && product(1, 0) == m(1, 0) + T(3) * m(1, 2), true);
    vnl_matrix_fixed<T, 2, 3> other(T(1));
    ref = other;
    TEST("assignment copies into the matrix" + in, m(1, 1) == T(1), true);
    TEST("as_matrix copies" + in, cref.as_matrix()(1, 2) == T(1), true);
  }
};

void test_matrix_fixed_ref() { for_each_test_scalar<CheckMatrixFixedRef>(); }

}  // namespace

TESTMAIN(test_matrix_fixed_ref)
