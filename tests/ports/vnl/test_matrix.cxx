// SPDX-License-Identifier: BSD-3-Clause
// vnl_matrix and vnl_matrix_fixed behave as upstream's: row-major storage, transpose, products,
// rows and columns, blocks and norms.
#include <string>

#include "testlib/testlib_test.h"
#include "vnl/vnl_matrix.h"
#include "vnl/vnl_matrix.hxx"
#include "vnl/vnl_matrix_fixed.h"
#include "vnl_test_types.h"

namespace {

template <class T>
struct CheckMatrix {
  static void run(const std::string& type) {
    const std::string in = " (" + type + ")";
    const T data[6] = {T(1), T(2), T(3), T(4), T(5), T(6)};
    const vnl_matrix<T> m(data, 2, 3);
    TEST("vnl_matrix(data, 2, 3) has 2 rows and 3 columns" + in, m.rows() == 2 && m.cols() == 3, true);
    TEST_NEAR("storage is row-major" + in, m(1, 0), 4.0, 0.0);
    TEST_NEAR("m[r][c] reads row r" + in, m[1][2], 6.0, 0.0);

    const vnl_matrix<T> t = m.transpose();
    TEST("transpose swaps the dimensions" + in, t.rows() == 3 && t.cols() == 2, true);
    TEST_NEAR("transpose moves (0,1) to (1,0)" + in, t(1, 0), 2.0, 0.0);
    vnl_matrix<T> u = m;
    u.inplace_transpose();
    TEST("inplace_transpose equals transpose" + in, u == t, true);

    const vnl_matrix<T> p = m * t;  // [[14, 32], [32, 77]]
    TEST_NEAR("m * m^T (0,0)" + in, p(0, 0), 14.0, 0.0);
    TEST_NEAR("m * m^T (0,1)" + in, p(0, 1), 32.0, 0.0);
    TEST_NEAR("m * m^T (1,1)" + in, p(1, 1), 77.0, 0.0);

    const T xs[3] = {T(1), T(0), T(-1)};
    const vnl_vector<T> mv = m * vnl_vector<T>(xs, 3);
    TEST_NEAR("m * v (row 1)" + in, mv[1], -2.0, 0.0);
    const T ys[2] = {T(1), T(1)};
    const vnl_vector<T> vm = vnl_vector<T>(ys, 2) * m;
    TEST_NEAR("v^T * m (column 2)" + in, vm[2], 9.0, 0.0);

    TEST_NEAR("get_row(1)[1]" + in, m.get_row(1)[1], 5.0, 0.0);
    TEST_NEAR("get_column(2)[0]" + in, m.get_column(2)[0], 3.0, 0.0);
    vnl_matrix<T> w(2, 3);
    w.set_row(0, m.get_row(1));
    w.set_column(2, m.get_column(0));
    TEST_NEAR("set_row copies a row" + in, w(0, 1), 5.0, 0.0);
    TEST_NEAR("set_column copies a column" + in, w(1, 2), 4.0, 0.0);

    const vnl_matrix<T> block = m.extract(2, 2, 0, 1);
    TEST_NEAR("extract takes the block at (0,1)" + in, block(1, 1), 6.0, 0.0);
    vnl_matrix<T> big(3, 4);
    big.update(block, 1, 2);
    TEST_NEAR("update writes the block at (1,2)" + in, big(2, 3), 6.0, 0.0);

    vnl_matrix<T> id(3, 3);
    id.set_identity();
    TEST("set_identity is the identity" + in, id.is_identity(T(0)), true);
    TEST_NEAR("frobenius_norm of I3 is sqrt(3)" + in, id.frobenius_norm(), 1.7320508075688772, ulps<T>(16));
    TEST_NEAR("absolute_value_max" + in, (-m).absolute_value_max(), 6.0, 0.0);
    TEST_NEAR("(m + m - m) * 2 / 2 is m" + in, (((m + m) - m) * T(2) / T(2))(1, 2), 6.0, 0.0);
    TEST_NEAR("outer_product" + in, outer_product(vnl_vector<T>(xs, 3), vnl_vector<T>(ys, 2))(2, 1), -1.0, 0.0);

    vnl_matrix_fixed<T, 2, 3> f(data);
    TEST_NEAR("vnl_matrix_fixed is row-major" + in, f(1, 0), 4.0, 0.0);
    const vnl_matrix_fixed<T, 2, 2> ff = f * f.transpose();
    TEST_NEAR("vnl_matrix_fixed product" + in, ff(1, 1), 77.0, 0.0);
    const vnl_vector_fixed<T, 2> fv = f * vnl_vector_fixed<T, 3>(xs);
    TEST_NEAR("vnl_matrix_fixed times vnl_vector_fixed" + in, fv[0], -2.0, 0.0);
    TEST("as_matrix copies to a vnl_matrix" + in, f.as_matrix() == m, true);
    vnl_matrix_fixed<T, 3, 3> i3;
    i3.set_identity();
    TEST("vnl_matrix_fixed set_identity" + in, i3.is_identity(T(0)), true);
    TEST_NEAR("vnl_matrix_fixed get_column" + in, f.get_column(1)[1], 5.0, 0.0);
  }
};

void test_matrix() { for_each_test_scalar<CheckMatrix>(); }

}  // namespace

TESTMAIN(test_matrix)
