// SPDX-License-Identifier: BSD-3-Clause
// vnl_vector and vnl_vector_fixed behave as upstream's: sizes, arithmetic, norms and products.
#include <sstream>
#include <string>

#include "testlib/testlib_test.h"
#include "vnl/vnl_vector.h"
#include "vnl/vnl_vector.hxx"
#include "vnl/vnl_vector_fixed.h"
#include "vnl_test_types.h"

namespace {

template <class T>
struct CheckVector {
  static void run(const std::string& type) {
    const std::string in = " (" + type + ")";
    vnl_vector<T> v(4, T(2));
    TEST("vnl_vector(n, value) has n elements" + in, v.size(), 4u);
    TEST("vnl_vector(n, value) fills with value" + in, v[3] == T(2), true);
    vnl_vector<T> zero(3);
    TEST("vnl_vector(n) starts at zero" + in, zero[0] == T(0) && zero[2] == T(0), true);

    const T data[4] = {T(3), T(-4), T(0), T(12)};
    const vnl_vector<T> a(data, 4);
    TEST_NEAR("two_norm of (3,-4,0,12) is 13" + in, a.two_norm(), 13.0, ulps<T>(64));
    TEST_NEAR("squared_magnitude of (3,-4,0,12) is 169" + in, a.squared_magnitude(), 169.0, ulps<T>(256));
    TEST_NEAR("one_norm of (3,-4,0,12) is 19" + in, a.one_norm(), 19.0, 0.0);
    TEST_NEAR("inf_norm of (3,-4,0,12) is 12" + in, a.inf_norm(), 12.0, 0.0);
    TEST_NEAR("sum of (3,-4,0,12) is 11" + in, a.sum(), 11.0, 0.0);
    TEST_NEAR("rms of (3,-4,0,12) is 13/2" + in, a.rms(), 6.5, ulps<T>(64));
    TEST_NEAR("min_value is -4" + in, a.min_value(), -4.0, 0.0);
    TEST_NEAR("max_value is 12" + in, a.max_value(), 12.0, 0.0);

    const vnl_vector<T> b = a + v;
    TEST_NEAR("a + v adds element-wise" + in, b[1], -2.0, 0.0);
    const vnl_vector<T> c = a - v;
    TEST_NEAR("a - v subtracts element-wise" + in, c[3], 10.0, 0.0);
    const vnl_vector<T> d = a * T(3);
    TEST_NEAR("a * 3 scales" + in, d[1], -12.0, 0.0);
    const vnl_vector<T> e = T(2) * a;
    TEST_NEAR("2 * a scales" + in, e[3], 24.0, 0.0);
    const vnl_vector<T> f = a / T(2);
    TEST_NEAR("a / 2 divides" + in, f[0], 1.5, 0.0);
    TEST_NEAR("unary minus negates" + in, (-a)[3], -12.0, 0.0);
    TEST_NEAR("dot_product(a, v) is 2 * sum(a)" + in, dot_product(a, v), 22.0, 0.0);
    TEST_NEAR("element_product multiplies element-wise" + in, element_product(a, a)[1], 16.0, 0.0);
    TEST_NEAR("vnl_vector_ssd(a, a) is 0" + in, vnl_vector_ssd(a, a), 0.0, 0.0);

    const vnl_vector<T> part = a.extract(2, 1);
    TEST("extract(2, 1) has 2 elements" + in, part.size(), 2u);
    TEST_NEAR("extract(2, 1) starts at element 1" + in, part[0], -4.0, 0.0);
    vnl_vector<T> target(5);
    target.update(part, 3);
    TEST_NEAR("update writes at the offset" + in, target[4], 0.0, 0.0);
    TEST_NEAR("update writes the first element at the offset" + in, target[3], -4.0, 0.0);

    vnl_vector<T> unit(data, 4);
    unit.normalize();
    TEST_NEAR("normalize gives a unit vector" + in, unit.two_norm(), 1.0, ulps<T>(64));
    vnl_vector<T> z(2);
    z.normalize();
    TEST("normalize leaves a zero vector alone" + in, z[0] == T(0), true);

    const T x[3] = {T(1), T(0), T(0)};
    const T y[3] = {T(0), T(1), T(0)};
    const vnl_vector<T> cross = vnl_cross_3d(vnl_vector<T>(x, 3), vnl_vector<T>(y, 3));
    TEST_NEAR("x cross y is z" + in, cross[2], 1.0, 0.0);

    const vnl_vector_fixed<T, 3> p(T(1), T(2), T(2));
    TEST_NEAR("vnl_vector_fixed two_norm of (1,2,2) is 3" + in, p.two_norm(), 3.0, ulps<T>(16));
    const vnl_vector_fixed<T, 3> q = p * T(2) - p;
    TEST("vnl_vector_fixed arithmetic matches by element" + in, q == p, true);
    const vnl_vector_fixed<T, 3> r = vnl_cross_3d(vnl_vector_fixed<T, 3>(x), vnl_vector_fixed<T, 3>(y));
    TEST_NEAR("vnl_vector_fixed x cross y is z" + in, r[2], 1.0, 0.0);
    TEST_NEAR("vnl_vector_fixed dot_product" + in, dot_product(p, p), 9.0, 0.0);
    const vnl_vector<T> heap = p.as_vector();
    TEST("as_vector copies to a vnl_vector" + in, heap.size() == 3 && heap[2] == T(2), true);
    const bool same = vnl_vector_fixed<T, 3>(heap) == p;
    TEST("vnl_vector_fixed from a vnl_vector" + in, same, true);

    std::ostringstream out;
    out << vnl_vector<T>(data, 2);
    TEST("operator<< prints the elements separated by a space" + in, out.str(), std::string("3 -4"));
  }
};

void test_vector() { for_each_test_scalar<CheckVector>(); }

}  // namespace

TESTMAIN(test_vector)
