// SPDX-License-Identifier: BSD-3-Clause
// The vector and matrix arithmetic as upstream's test_arithmetic.cxx (its body in
// test_arithmetic_body.h): construction from data, (in)equality, assignment, + - * / with
// containers and scalars on either side, the compound forms, matrix times vector, element
// products and quotients and negation; each on vnl_vector/vnl_matrix, on the _ref views and
// on the _fixed types, for double, float and the configured real. Every value is exact in
// each scalar (the quotients are computed in it), so all comparisons are ==.
#include <array>
#include <string>

#include "testlib/testlib_test.h"
#include "vnl/vnl_matrix.h"
#include "vnl/vnl_matrix_fixed.h"
#include "vnl/vnl_matrix_ref.h"
#include "vnl/vnl_vector.h"
#include "vnl/vnl_vector_fixed.h"
#include "vnl/vnl_vector_ref.h"
#include "vnl_test_types.h"

namespace {
// How each kind of container is made over a data array (upstream's NewMat / NewVec macros).
template <class T>
struct dynamic_kind {
  static constexpr const char* name = "dynamic";
  template <unsigned R, unsigned C>
  static vnl_matrix<T> mat(T* d) {
    return vnl_matrix<T>(d, R, C);
  }
  template <unsigned N>
  static vnl_vector<T> vec(T* d) {
    return vnl_vector<T>(d, N);
  }
};
template <class T>
struct ref_kind {
  static constexpr const char* name = "ref";
  template <unsigned R, unsigned C>
  static vnl_matrix_ref<T> mat(T* d) {
    return vnl_matrix_ref<T>(R, C, d);
  }
  template <unsigned N>
  static vnl_vector_ref<T> vec(T* d) {
    return vnl_vector_ref<T>(N, d);
  }
};
template <class T>
struct fixed_kind {
  static constexpr const char* name = "fixed";
  template <unsigned R, unsigned C>
  static vnl_matrix_fixed<T, R, C> mat(T* d) {
    return vnl_matrix_fixed<T, R, C>(d);
  }
  template <unsigned N>
  static vnl_vector_fixed<T, N> vec(T* d) {
    return vnl_vector_fixed<T, N>(d);
  }
};

template <class T, std::size_t N>
std::array<T, N> values(const int (&v)[N]) {
  std::array<T, N> out;
  for (std::size_t i = 0; i < N; ++i) out[i] = T(v[i]);
  return out;
}

template <class T, template <class> class Kind>
void check_construction_and_assignment(const std::string& p) {
  using K = Kind<T>;
  auto m1_data = values<T>({1, 2, 3, 4, 5, 6}), m3_data = values<T>({3, 4, 5, 6, 7, 8});
  auto v1_data = values<T>({3, 2}), v3_data = values<T>({1, 2, 3}), v2_data = values<T>({1, 4});
  auto m1_copy = m1_data, v1_copy = v1_data;
  std::array<T, 100> tmp{};
  const auto m1 = K::template mat<3, 2>(m1_data.data());
  TEST((p + "3x2 matrix construction").c_str(),
       m1.rows() == 3 && m1.cols() == 2 && m1(0, 0) == T(1) && m1(0, 1) == T(2) && m1(1, 0) == T(3) &&
           m1(1, 1) == T(4) && m1(2, 0) == T(5) && m1(2, 1) == T(6),
       true);
  const auto m3 = K::template mat<2, 3>(m3_data.data());
  TEST((p + "2x3 matrix construction").c_str(),
       m3.rows() == 2 && m3.cols() == 3 && m3(0, 0) == T(3) && m3(0, 2) == T(5) && m3(1, 0) == T(6) && m3(1, 2) == T(8),
       true);
  const auto v1 = K::template vec<2>(v1_data.data());
  TEST((p + "2 vector construction").c_str(), v1.size() == 2 && v1[0] == T(3) && v1[1] == T(2), true);
  const auto v3 = K::template vec<3>(v3_data.data());
  TEST((p + "3 vector construction").c_str(), v3.size() == 3 && v3[0] == T(1) && v3[2] == T(3), true);
  const auto v2 = K::template vec<2>(v2_data.data());
  const auto m1_orig = K::template mat<3, 2>(m1_copy.data());
  const auto v1_orig = K::template vec<2>(v1_copy.data());
  TEST((p + "equality").c_str(), v1 == v1_orig && !(v1 == v2), true);
  TEST((p + "inequality").c_str(), !(v1 != v1_orig) && v1 != v2, true);

  auto v_result_data = values<T>({9, 2});
  const auto v_result = K::template vec<2>(v_result_data.data());
  auto tv = K::template vec<2>(tmp.data());
  tv = v1;
  tv(0) = T(9);
  TEST((p + "assignment on vector").c_str(), tv == v_result && v1 == v1_orig, true);
  auto m_result_data = values<T>({1, 2, 3, 8, 5, 6});
  const auto m_result = K::template mat<3, 2>(m_result_data.data());
  auto tm = K::template mat<3, 2>(tmp.data());
  tm = m1;
  tm(1, 1) = T(8);
  TEST((p + "assignment on matrix").c_str(), tm == m_result && m1 == m1_orig, true);
}

template <class T, template <class> class Kind>
void check_sums_and_differences(const std::string& p) {
  using K = Kind<T>;
  auto m1_data = values<T>({1, 2, 3, 4, 5, 6}), m2_data = values<T>({7, 8, 9, 1, 2, 3});
  auto v1_data = values<T>({3, 2}), v2_data = values<T>({1, 4});
  auto m1_copy = m1_data, m2_copy = m2_data, v1_copy = v1_data, v2_copy = v2_data;
  std::array<T, 100> tmp{};
  const auto m1 = K::template mat<3, 2>(m1_data.data()), m2 = K::template mat<3, 2>(m2_data.data());
  const auto v1 = K::template vec<2>(v1_data.data()), v2 = K::template vec<2>(v2_data.data());
  const auto m1_orig = K::template mat<3, 2>(m1_copy.data()), m2_orig = K::template mat<3, 2>(m2_copy.data());
  const auto v1_orig = K::template vec<2>(v1_copy.data()), v2_orig = K::template vec<2>(v2_copy.data());

  auto v_add1_data = values<T>({4, 6}), v_add2_data = values<T>({8, 7});
  const auto v_add1 = K::template vec<2>(v_add1_data.data()), v_add2 = K::template vec<2>(v_add2_data.data());
  auto tv = K::template vec<2>(tmp.data());
  tv = v1;
  tv += v2;
  TEST((p + "v += v").c_str(), tv == v_add1 && v2 == v2_orig, true);
  TEST((p + "v + v").c_str(), v1 + v2 == v_add1 && v1 == v1_orig && v2 == v2_orig, true);
  tv = v1;
  tv += T(5);
  TEST((p + "v += s").c_str(), tv == v_add2, true);
  TEST((p + "v + s, s + v").c_str(), v1 + T(5) == v_add2 && T(5) + v1 == v_add2 && v1 == v1_orig, true);
  auto m_add1_data = values<T>({8, 10, 12, 5, 7, 9}), m_add2_data = values<T>({4, 5, 6, 7, 8, 9});
  const auto m_add1 = K::template mat<3, 2>(m_add1_data.data()), m_add2 = K::template mat<3, 2>(m_add2_data.data());
  auto tm = K::template mat<3, 2>(tmp.data());
  tm = m1;
  tm += m2;
  TEST((p + "m += m").c_str(), tm == m_add1 && m2 == m2_orig, true);
  TEST((p + "m + m").c_str(), m1 + m2 == m_add1 && m1 == m1_orig && m2 == m2_orig, true);
  tm = m1;
  tm += T(3);
  TEST((p + "m += s").c_str(), tm == m_add2, true);
  TEST((p + "m + s, s + m").c_str(), m1 + T(3) == m_add2 && T(3) + m1 == m_add2 && m1 == m1_orig, true);

  auto v_sub1_data = values<T>({2, -2}), v_sub2_data = values<T>({2, 1}), v_sub3_data = values<T>({-2, -1});
  const auto v_sub1 = K::template vec<2>(v_sub1_data.data()), v_sub2 = K::template vec<2>(v_sub2_data.data()),
             v_sub3 = K::template vec<2>(v_sub3_data.data());
  tv = v1;
  tv -= v2;
  TEST((p + "v -= v").c_str(), tv == v_sub1 && v2 == v2_orig, true);
  TEST((p + "v - v").c_str(), v1 - v2 == v_sub1 && v1 == v1_orig && v2 == v2_orig, true);
  tv = v1;
  tv -= T(1);
  TEST((p + "v -= s").c_str(), tv == v_sub2, true);
  TEST((p + "v - s, s - v").c_str(), v1 - T(1) == v_sub2 && T(1) - v1 == v_sub3 && v1 == v1_orig, true);
  auto m_sub1_data = values<T>({-6, -6, -6, 3, 3, 3}), m_sub2_data = values<T>({0, 1, 2, 3, 4, 5}),
       m_sub3_data = values<T>({0, -1, -2, -3, -4, -5});
  const auto m_sub1 = K::template mat<3, 2>(m_sub1_data.data()), m_sub2 = K::template mat<3, 2>(m_sub2_data.data()),
             m_sub3 = K::template mat<3, 2>(m_sub3_data.data());
  tm = m1;
  tm -= m2;
  TEST((p + "m -= m").c_str(), tm == m_sub1 && m2 == m2_orig, true);
  TEST((p + "m - m").c_str(), m1 - m2 == m_sub1 && m1 == m1_orig && m2 == m2_orig, true);
  tm = m1;
  tm -= T(1);
  TEST((p + "m -= s").c_str(), tm == m_sub2, true);
  TEST((p + "m - s, s - m").c_str(), m1 - T(1) == m_sub2 && T(1) - m1 == m_sub3 && m1 == m1_orig, true);
}

template <class T, template <class> class Kind>
void check_products_and_quotients(const std::string& p) {
  using K = Kind<T>;
  auto m1_data = values<T>({1, 2, 3, 4, 5, 6}), m2_data = values<T>({7, 8, 9, 1, 2, 3});
  auto v1_data = values<T>({3, 2}), v2_data = values<T>({1, 4});
  auto m1_copy = m1_data, v1_copy = v1_data;
  std::array<T, 100> tmp{};
  const auto m1 = K::template mat<3, 2>(m1_data.data()), m2 = K::template mat<3, 2>(m2_data.data());
  const auto v1 = K::template vec<2>(v1_data.data()), v2 = K::template vec<2>(v2_data.data());
  const auto m1_orig = K::template mat<3, 2>(m1_copy.data());
  const auto v1_orig = K::template vec<2>(v1_copy.data());

  auto v_mul1_data = values<T>({9, 6}), v_mul2_data = values<T>({7, 17, 27});
  const auto v_mul1 = K::template vec<2>(v_mul1_data.data());
  const auto v_mul2 = K::template vec<3>(v_mul2_data.data());
  auto tv = K::template vec<2>(tmp.data());
  tv = v1;
  tv *= T(3);
  TEST((p + "v *= s").c_str(), tv == v_mul1, true);
  TEST((p + "v * s, s * v").c_str(), v1 * T(3) == v_mul1 && T(3) * v1 == v_mul1 && v1 == v1_orig, true);
  auto m_mul1_data = values<T>({2, 4, 6, 8, 10, 12});
  const auto m_mul1 = K::template mat<3, 2>(m_mul1_data.data());
  auto tm = K::template mat<3, 2>(tmp.data());
  tm = m1;
  tm *= T(2);
  TEST((p + "m *= s").c_str(), tm == m_mul1, true);
  TEST((p + "m * s, s * m").c_str(), m1 * T(2) == m_mul1 && T(2) * m1 == m_mul1 && m1 == m1_orig, true);
  TEST((p + "m * v").c_str(), m1 * v1 == v_mul2, true);

  std::array<T, 2> v_div1_data{T(3) / T(2), T(1)};
  const auto v_div1 = K::template vec<2>(v_div1_data.data());
  tv = v1;
  tv /= T(2);
  TEST((p + "v /= s").c_str(), tv == v_div1, true);
  TEST((p + "v / s").c_str(), v1 / T(2) == v_div1 && v1 == v1_orig, true);
  std::array<T, 6> m_div1_data{T(1) / T(2), T(1), T(3) / T(2), T(2), T(5) / T(2), T(3)};
  const auto m_div1 = K::template mat<3, 2>(m_div1_data.data());
  tm = m1;
  tm /= T(2);
  TEST((p + "m /= s").c_str(), tm == m_div1, true);
  TEST((p + "m / s").c_str(), m1 / T(2) == m_div1 && m1 == m1_orig, true);

  auto v_ep1_data = values<T>({3, 8}), m_ep1_data = values<T>({7, 16, 27, 4, 10, 18});
  TEST((p + "element_product(v, v)").c_str(), element_product(v1, v2) == (K::template vec<2>(v_ep1_data.data())), true);
  TEST((p + "element_product(m, m)").c_str(), element_product(m1, m2) == (K::template mat<3, 2>(m_ep1_data.data())),
       true);
  std::array<T, 2> v_eq1_data{T(3), T(1) / T(2)};
  std::array<T, 6> m_eq1_data{T(1) / T(7), T(2) / T(8), T(3) / T(9), T(4), T(5) / T(2), T(2)};
  TEST((p + "element_quotient(v, v)").c_str(), element_quotient(v1, v2) == (K::template vec<2>(v_eq1_data.data())),
       true);
  TEST((p + "element_quotient(m, m)").c_str(), element_quotient(m1, m2) == (K::template mat<3, 2>(m_eq1_data.data())),
       true);

  auto v_neg1_data = values<T>({-3, -2}), m_neg1_data = values<T>({-1, -2, -3, -4, -5, -6});
  TEST((p + "-v").c_str(), -v1 == (K::template vec<2>(v_neg1_data.data())) && v1 == v1_orig, true);
  TEST((p + "-m").c_str(), -m1 == (K::template mat<3, 2>(m_neg1_data.data())) && m1 == m1_orig, true);
}

template <class T>
struct check_arithmetic {
  template <template <class> class Kind>
  static void on(const std::string& scalar) {
    const std::string prefix = scalar + ", " + Kind<T>::name + ": ";
    check_construction_and_assignment<T, Kind>(prefix);
    check_sums_and_differences<T, Kind>(prefix);
    check_products_and_quotients<T, Kind>(prefix);
  }
  static void run(const std::string& scalar) {
    on<dynamic_kind>(scalar);
    on<ref_kind>(scalar);
    on<fixed_kind>(scalar);
  }
};
}  // namespace

static void test_arithmetic() { for_each_test_scalar<check_arithmetic>(); }

TESTMAIN(test_arithmetic)
