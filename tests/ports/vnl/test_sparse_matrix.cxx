// SPDX-License-Identifier: BSD-3-Clause
// vnl_sparse_matrix as upstream's test_sparse_matrix.cxx: element access without insertion,
// copies, equality, transpose, sums, scalar and matrix products, vector products, iteration.
#include <string>
#include <vector>

#include "testlib/testlib_test.h"
#include "vnl/vnl_sparse_matrix.h"
#include "vnl/vnl_vector.h"
#include "vnl_test_types.h"

namespace {

template <class T>
struct CheckSparse {
  static void run(const std::string& type) {
    const std::string in = " (" + type + ")";
    vnl_sparse_matrix<T> m0(200, 300);
    TEST("vnl_sparse_matrix m0(200,300) rows" + in, m0.rows(), 200u);
    TEST("columns" + in, m0.columns(), 300u);
    m0(3, 7) = T(2);
    m0(3, 2) = T(-1);
    m0(150, 299) = T(5);
    TEST("(vnl_sparse_matrix)(i,j) writes" + in, m0(3, 7) == T(2), true);
    const vnl_sparse_matrix<T>& c0 = m0;
    TEST("(const vnl_sparse_matrix)(i,j) of an absent element is 0" + in, c0(10, 10) == T(0), true);
    TEST("reading through const inserts nothing" + in, m0.get_row(10).empty(), true);
    TEST("a row keeps its columns sorted" + in, m0.get_row(3)[0].first, 2u);
    vnl_sparse_matrix<T> m1(m0);
    TEST("copy constructor" + in, m1 == m0, true);
    m1.put(1, 1, T(3));
    TEST("m1.put(1,1,3); m1.get(1,1)" + in, m1.get(1, 1) == T(3), true);
    TEST("m0 != m1" + in, m0 != m1, true);

    const vnl_sparse_matrix<T> t = m0.transpose();
    TEST("transpose size" + in, t.rows() == 300u && t.columns() == 200u, true);
    TEST("transpose content" + in, t(299, 150) == T(5) && t(7, 3) == T(2), true);
    TEST("mb = -m0" + in, (-m0)(3, 2) == T(1), true);
    const vnl_sparse_matrix<T> sum = m0 + m1;
    TEST("mb=m1+m2" + in, sum(3, 7) == T(4) && sum(1, 1) == T(3), true);
    const vnl_sparse_matrix<T> difference = m1 - m0;
    TEST("mb=m1-m2 keeps the difference" + in, difference(1, 1) == T(3) && difference(3, 7) == T(0), true);
    vnl_sparse_matrix<T> acc(m1);
    acc += m0;
    acc -= m0;
    TEST("m1 += m2; m1 -= m2" + in, acc.get(3, 7) == T(2) && acc.get(1, 1) == T(3), true);
    TEST("mb=m1*5" + in, (m1 * T(5))(150, 299) == T(25), true);
    TEST("mb=5*m1" + in, (T(5) * m1)(3, 2) == T(-5), true);
    vnl_sparse_matrix<T> scaled(m1);
    scaled *= T(4);
    scaled /= T(2);
    TEST("m1*=4; m1/=2" + in, scaled(3, 7) == T(4), true);

    // Products against dense results.
    vnl_sparse_matrix<T> a(3, 4), b(4, 2);
    a(0, 0) = T(1), a(0, 3) = T(2), a(1, 1) = T(-1), a(2, 2) = T(3), a(2, 3) = T(1);
    b(0, 1) = T(2), b(1, 0) = T(4), b(3, 0) = T(1), b(3, 1) = T(-1);
    const vnl_sparse_matrix<T> ab = a * b;
    TEST("a*b (0,0)" + in, ab(0, 0) == T(2), true);
    TEST("a*b (0,1)" + in, ab(0, 1) == T(0), true);
    TEST("a*b (1,0)" + in, ab(1, 0) == T(-4), true);
    TEST("a*b (2,1)" + in, ab(2, 1) == T(-1), true);
    vnl_vector<T> x(4);
    x[0] = T(1), x[1] = T(2), x[2] = T(3), x[3] = T(4);
    const vnl_vector<T> ax = a * x;
    TEST("a*x" + in, ax[0] == T(9) && ax[1] == T(-2) && ax[2] == T(13), true);
    // A dense 4 x 2 block times a, both column-major as upstream's raw mult takes them: the
    // columns of p are x and (1, 0, 0, 1); q's column 0 is a * x.
    const T p[8] = {T(1), T(2), T(3), T(4), T(1), T(0), T(0), T(1)};
    T q[6];
    a.mult(4, 2, p, q);
    TEST("raw mult: column-major result" + in,
         q[0] == T(9) && q[1] == T(-2) && q[2] == T(13) && q[3] == T(3) && q[4] == T(0) && q[5] == T(1), true);
    vnl_vector<T> y(3, T(1)), ya;
    a.pre_mult(y, ya);
    TEST("y^T a" + in, ya.size() == 4u && ya[3] == T(3) && ya[1] == T(-1), true);
    vnl_vector<T> d;
    a.diag_AtA(d);
    TEST("diag(A^T A)" + in, d[3] == T(5) && d[2] == T(9), true);

    int count = 0;
    T total(0);
    for (a.reset(); a.next();) {
      ++count;
      total += a.value() * T(a.getrow() + 1);
    }
    TEST("iteration visits every stored element once" + in, count, 5);
    TEST("iteration reports rows and values" + in, total == T(1 + 2 - 2 + 9 + 3), true);
    vnl_sparse_matrix<T> id(3, 3);
    id.set_identity();
    TEST("set_identity: I * a is a" + in, id * a == a, true);
    TEST("sum_row" + in, a.sum_row(0) == T(3), true);
    std::vector<int> cols = {2, 0};
    std::vector<T> vals = {T(7), T(8)};
    a.set_row(1, cols, vals);
    TEST("set_row sorts the new row" + in, a.get_row(1)[0].first == 0u && a(1, 2) == T(7), true);
  }
};

void test_sparse_matrix() {
  CheckSparse<int>::run("int");
  for_each_test_scalar<CheckSparse>();
}

}  // namespace

TESTMAIN(test_sparse_matrix)
