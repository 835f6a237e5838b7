// SPDX-License-Identifier: BSD-3-Clause
// vnl_matrix and vnl_matrix_fixed behave as upstream's: row-major storage, transpose, products,
// rows and columns, blocks and norms.
#include <cmath>
#include <complex>
#include <sstream>
#include <string>

#include "testlib/testlib_test.h"
#include "vnl/vnl_matrix.h"
#include "vnl/vnl_matrix.hxx"
#include "vnl/vnl_matrix_ref.h"
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

/// The rest of upstream's vnl_matrix interface: scalar operators, set_diagonal, views,
/// reordering, norms, row and column selection, comparison and text input.
template <class T>
struct CheckMatrixApi {
  static void run(const std::string& type) {
    const std::string in = " (" + type + ")";
    const vnl_matrix<T> m{{T(1), T(-2), T(3)}, {T(-4), T(5), T(-6)}};
    TEST("nested initializer lists" + in, m.rows() == 2u && m.cols() == 3u && m(1, 0) == T(-4), true);
    TEST("matrix + scalar" + in, (m + T(1))(0, 1) == T(-1), true);
    TEST("scalar - matrix" + in, (T(1) - m)(1, 1) == T(-4), true);
    TEST("scalar * matrix" + in, (T(2) * m)(1, 2) == T(-12), true);
    vnl_matrix<T> d(3, 3, T(0));
    d.set_diagonal(vnl_vector<T>{T(1), T(2), T(3)});
    TEST("set_diagonal" + in, d(2, 2) == T(3) && d(0, 1) == T(0), true);
    TEST("vnl_matrix_identity constructor" + in, vnl_matrix<T>(3, 3, vnl_matrix_identity).is_identity(), true);
    TEST("operator_one_norm: largest column sum" + in, m.operator_one_norm() == T(9), true);
    TEST("operator_inf_norm: largest row sum" + in, m.operator_inf_norm() == T(15), true);
    TEST("array_one_norm" + in, m.array_one_norm() == T(21), true);
    TEST("array_inf_norm" + in, m.array_inf_norm() == T(6), true);
    TEST("min_value, arg_max" + in, m.min_value() == T(-6) && m.arg_max() == 4u, true);
    vnl_matrix<T> f(m);
    f.flipud();
    TEST("flipud" + in, f(0, 0) == T(-4), true);
    f.fliplr();
    TEST("fliplr" + in, f(0, 0) == T(-6), true);
    vnl_matrix<T> n{{T(3), T(4)}, {T(0), T(0)}};
    n.normalize_rows();
    TEST_NEAR("normalize_rows" + in, n(0, 1), 0.8, ulps<T>(4));
    TEST("normalize_rows leaves a zero row" + in, n(1, 0) == T(0), true);
    vnl_vector<unsigned> pick{2u, 0u};
    TEST("get_columns" + in, m.get_columns(pick)(1, 0) == T(-6) && m.get_columns(pick)(0, 1) == T(1), true);
    TEST("get_rows" + in, m.get_rows(vnl_vector<unsigned>{1u})(0, 2) == T(-6), true);
    TEST("get_n_columns" + in, m.get_n_columns(1, 2)(1, 1) == T(-6), true);
    TEST("flatten_column_major" + in, m.flatten_column_major()[1] == T(-4), true);
    TEST("is_equal within a tolerance" + in, m.is_equal(m + T(0.25), 0.5) && !m.is_equal(m + T(1), 0.5), true);
    T block[4] = {T(1), T(2), T(3), T(4)};
    vnl_matrix_ref<T> ref(2, 2, block);
    ref(1, 0) = T(-3);
    TEST("vnl_matrix_ref writes its block" + in, block[2] == T(-3), true);
    ref *= T(2);
    TEST("vnl_matrix_ref arithmetic writes its block" + in, block[3] == T(8), true);
    TEST("data_array rows" + in, ref.data_array()[1][1] == T(8), true);
    vnl_matrix<T> grow;
    grow.set_size(2, 2);
    grow *= ref;
    TEST("operator*= by a matrix" + in, grow.is_zero(), true);
    std::istringstream text("1 2 3\n4 5 6\n");
    vnl_matrix<T> read;
    read.read_ascii(text);
    TEST("read_ascii of an empty matrix reads its rows" + in, read.rows() == 2u && read.cols() == 3u && read(1, 2) == T(6),
         true);
    TEST("element_product" + in, element_product(m, m)(1, 2) == T(36), true);
    TEST("scale_row, scale_column" + in, vnl_matrix<T>(m).scale_row(1, T(2)).scale_column(0, T(-1))(1, 0) == T(8),
         true);
  }
};

void test_matrix() {
  for_each_test_scalar<CheckMatrix>();
  for_each_test_scalar<CheckMatrixApi>();
  // Integer and complex matrices, as upstream instantiates them.
  const vnl_matrix<int> im{{1, 2}, {3, 4}};
  TEST("vnl_matrix<int> product", (im * im)(1, 1), 22);
  const vnl_matrix<std::complex<double>> cm{{{1, 1}, {0, 2}}, {{3, 0}, {0, -1}}};
  TEST("conjugate_transpose conjugates and transposes", cm.conjugate_transpose()(1, 0), std::complex<double>(0, -2));
  TEST_NEAR("complex frobenius_norm", cm.frobenius_norm(), std::sqrt(2.0 + 4 + 9 + 1), 1e-15);
}

}  // namespace

TESTMAIN(test_matrix)
