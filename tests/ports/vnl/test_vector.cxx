// SPDX-License-Identifier: BSD-3-Clause
// vnl_vector and vnl_vector_fixed behave as upstream's: sizes, arithmetic, norms and products.
#include <cmath>
#include <complex>
#include <sstream>
#include <string>

#include "testlib/testlib_test.h"
#include "vnl/vnl_vector.h"
#include "vnl/vnl_vector.hxx"
#include "vnl/vnl_vector_fixed.h"
#include "vnl/vnl_vector_ref.h"
#include "vnl/vnl_matrix.h"
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

/// The rest of upstream's vnl_vector interface: scalar operators, views, reordering, search,
/// comparison with a tolerance and text input.
template <class T>
struct CheckVectorApi {
  static void run(const std::string& type) {
    const std::string in = " (" + type + ")";
    const vnl_vector<T> v{T(3), T(-1), T(4), T(1)};
    TEST("initializer list" + in, v.size() == 4u && v[2] == T(4), true);
    TEST("vector + scalar" + in, (v + T(1))[1] == T(0), true);
    TEST("scalar + vector" + in, (T(1) + v)[0] == T(4), true);
    TEST("scalar - vector" + in, (T(1) - v)[2] == T(-3), true);
    TEST("vector - scalar" + in, (v - T(1))[3] == T(0), true);
    TEST("scalar * vector" + in, (T(2) * v)[2] == T(8), true);
    TEST("arg_min is 1, arg_max is 2" + in, v.arg_min() == 1u && v.arg_max() == 2u, true);
    TEST("min_value, max_value" + in, v.min_value() == T(-1) && v.max_value() == T(4), true);
    TEST("roll(1) moves element 0 to 1" + in, v.roll(1)[1] == T(3) && v.roll(1)[0] == T(1), true);
    TEST("roll(-1) moves element 1 to 0" + in, v.roll(-1)[0] == T(-1), true);
    vnl_vector<T> f(v);
    f.flip();
    TEST("flip reverses" + in, f[0] == T(1) && f[3] == T(3), true);
    f.flip(1, 3);
    TEST("flip(1, 3) reverses elements 1 and 2" + in, f[1] == T(-1) && f[2] == T(4), true);
    TEST("is_equal within a tolerance" + in, v.is_equal(v + T(0.25), 0.5) && !v.is_equal(v + T(1), 0.5), true);
    TEST("is_zero" + in, vnl_vector<T>(3, T(0)).is_zero() && !v.is_zero(), true);
    TEST("is_finite" + in, v.is_finite(), true);
    T storage[3] = {T(1), T(2), T(3)};
    vnl_vector_ref<T> ref(3, storage);
    ref[1] = T(9);
    TEST("vnl_vector_ref writes its memory" + in, storage[1] == T(9), true);
    ref += T(1);
    TEST("vnl_vector_ref arithmetic writes its memory" + in, storage[2] == T(4), true);
    ref = vnl_vector<T>(3, T(-1));
    TEST("vnl_vector_ref assignment copies into its memory" + in, storage[0] == T(-1), true);
    vnl_vector<T> owner(2, T(0));
    owner.as_ref()[1] = T(5);
    TEST("as_ref views the vector" + in, owner[1] == T(5), true);
    vnl_vector<T> a(2, T(1)), b(3, T(2));
    a.swap(b);
    TEST("swap exchanges contents" + in, a.size() == 3u && b.size() == 2u && a[0] == T(2), true);
    std::istringstream text("1 2.5 -3");
    vnl_vector<T> read;
    read.read_ascii(text);
    TEST("read_ascii of an empty vector reads all values" + in, read.size() == 3u && read[2] == T(-3), true);
    TEST("element_quotient" + in, element_quotient(v, v)[2] == T(1), true);
    const vnl_vector<T> e0{T(1), T(0)}, e1{T(0), T(2)};
    TEST_NEAR("angle between perpendicular vectors is pi/2" + in, angle(e0, e1), 1.5707963267948966, ulps<T>(16));
    TEST("vnl_cross_2d" + in, vnl_cross_2d(e0, e1) == T(2), true);
    vnl_matrix<T> m(2, 4, T(1));
    vnl_vector<T> row(v);
    row.pre_multiply(m);
    TEST("pre_multiply: M v" + in, row.size() == 2u && row[0] == T(7), true);
  }
};

void test_vector() {
  for_each_test_scalar<CheckVector>();
  for_each_test_scalar<CheckVectorApi>();
  // Integer and complex vectors, as upstream instantiates them.
  const vnl_vector<int> iv{3, -4};
  TEST("vnl_vector<int> two_norm is 5 (abs_t unsigned)", iv.two_norm(), 5u);
  TEST("vnl_vector<int> one_norm", iv.one_norm(), 7u);
  const vnl_vector<std::complex<double>> cv{{3, 4}, {0, 1}};
  TEST_NEAR("vnl_vector<complex> two_norm is sqrt(26)", cv.two_norm(), std::sqrt(26.0), 1e-15);
  TEST_NEAR("inner_product conjugates the second", inner_product(cv, cv), std::complex<double>(26, 0), 1e-15);
  TEST_NEAR("dot_product does not", dot_product(cv, cv), std::complex<double>(-8, 24), 1e-15);
}

}  // namespace

TESTMAIN(test_vector)
