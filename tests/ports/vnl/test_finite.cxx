// SPDX-License-Identifier: BSD-3-Clause
// vnl_finite as upstream's test_finite.cxx. vnl_finite_int<N> for upstream's moduli (primes,
// prime powers, products, N up to 65537): construction modulo N, comparisons, sums and
// differences over a grid, products, Euler's theorem, division as the inverse of the product,
// orders, generators, exp and log. vnl_finite_int_poly<N, M> for upstream's four rings
// (GF(32), GF(27), Z_3[X] modulo a reducible cubic, Z_6[X] modulo X^2 + 1): construction,
// sums and differences over a grid, products modulo the modulus, multiplicative order and
// whether the ring is a field.
#include <sstream>
#include <string>
#include <vector>

#include "testlib/testlib_test.h"
#include "vnl/vnl_finite.h"

namespace {
template <int N>
void check_finite_int() {
  using Z = vnl_finite_int<N>;
  const std::string p = "Z_" + std::to_string(N) + ": ";
  const Z g = Z::smallest_generator();
  if (g != 1) TEST((p + "g^(phi(N)/2) == -1 for the generator").c_str(), g.pow(Z::totient() / 2), -1);
  TEST((p + "construction modulo N").c_str(),
       Z(0) == 0 && Z(1) == 1 && Z(-1) == N - 1 && Z(111) == 111 && Z(-99) == -99, true);
  Z b1;
  b1 = 10;
  TEST((p + "assignment reduces").c_str(), b1 == 10 - N && (b1 = -77) == 11 * N - 77, true);
  const Z b0 = 0, b2 = 2, b3 = -2;
  b1 = 1;
  TEST((p + "comparisons").c_str(),
       (b0 == b2) == (N == 2) && (b1 == b3) == (N == 3) && (b2 == b3) == (N == 2 || N == 4) && b0 != b1, true);
  int sum_errors = 0;
  for (int i = 1; i < 1000; i *= 3) {
    for (int j = 1; j < 1000; j *= 3) sum_errors += Z(i) + Z(j) != Z(i + j) || Z(i) - Z(j) != Z(i - j);
  }
  TEST((p + "sums and differences over a grid").c_str(), sum_errors, 0);
  const Z b1000(1000), b1000000(1000000);
  TEST((p + "negation").c_str(), -b0 == b0 && -b1000 == (-1) * b1000 && -(-b1000) == b1000, true);
  TEST((p + "-b1000 - b1000 == -2 * b1000").c_str(), -b1000 - b1000, -2 * b1000);
  const Z c2 = 1237, c3 = 4321;
  TEST((p + "(c2 + c3) - c2 == c3").c_str(), (c2 + c3) - c2, c3);
  TEST((p + "1000 * 1000 == 1000000").c_str(), b1000 * b1000, b1000000);
  if (b1000.is_unit()) {
    Z power = 1;
    for (unsigned phi = Z::totient(); phi > 0; --phi) power *= b1000;
    TEST((p + "Euler: 1000^phi(N) == 1").c_str(), power, 1);
  }
  if (c3.is_unit()) TEST((p + "(c2 * c3) / c3 == c2").c_str(), (c2 * c3) / c3, c2);
  if (N > 1000) return;  // the rest loops over N
  int division_errors = 0;
  for (int i = 10000; i > 0; i /= 3) {
    for (int j = 10000; j > 0; j /= 3) {
      for (int k = 1; k < 17; k += 3) {
        for (int l = 1; l < 17; l += 3) {
          const Z a(i + k), b(j + l);
          if (!b.is_unit()) continue;  // division by non-units is undefined
          division_errors += ((a / b) * b) != a;
        }
      }
    }
  }
  TEST((p + "(a / b) * b == a for units b").c_str(), division_errors, 0);
  const int order = Z(2).multiplicative_order();
  if (order > 0) TEST((p + "2^order(2) == 1").c_str(), Z(2).pow(order), 1);
  if (g != 1) {
    bool logs_ok = true;
    for (int x = 1; x < N; ++x) {
      if (Z(x).is_unit()) logs_ok = logs_ok && Z::exp(static_cast<int>(Z(x).log())) == Z(x);
    }
    TEST((p + "exp(log(x)) == x for every unit").c_str(), logs_ok, true);
  }
}

template <int N, int M>
void check_finite_poly(const std::string& modulus_text, bool is_field) {
  using P = vnl_finite_int_poly<N, M>;
  using Z = vnl_finite_int<N>;
  const std::string p = "Z_" + std::to_string(N) + "[X] mod " + modulus_text + ": ";
  TEST((p + "default is 0").c_str(), P(), 0);
  P b(std::vector<Z>(1, Z(1)));
  TEST((p + "from coefficients").c_str(), b, 1);
  b = Z(2);
  TEST((p + "from a scalar").c_str(), b, 2);
  TEST((p + "unary plus and minus").c_str(), +b == b && -b == N - 2, true);
  int errors = 0;
  for (int i = 1000; i > 0; i /= 3) {
    for (int j = 1000; j > 0; j /= 3) {
      std::vector<Z> v1(M), v2(M), v3(M);
      for (int m = 0; m < M; ++m) v1[m] = i + m, v2[m] = j + m, v3[m] = i + j + 2 * m;
      const P p1(v1), p2(v2), p3(v3);
      errors += p1 + p2 != p3 || p3 - p2 != p1;
    }
  }
  TEST((p + "sums and differences over a grid").c_str(), errors, 0);

  std::vector<Z> modulus(M + 1);
  std::istringstream digits(modulus_text);
  for (Z& c : modulus) {
    int value = 0;
    digits >> value;
    c = value;
  }
  std::vector<Z> x_to_the_m = P::modulo_polynomial(modulus);
  TEST((p + "the stored modulus has X^M coefficient -1").c_str(), x_to_the_m[M], -1);
  x_to_the_m.pop_back();
  const P irred = x_to_the_m;
  // X * X^(M-1) reduces to X^M's residue: the product really reduces modulo the modulus.
  std::vector<Z> x(M, Z(0)), x_m1(M, Z(0));
  x[1 % M] = 1, x_m1[M - 1] = 1;
  TEST((p + "X * X^(M-1) == X^M mod the modulus").c_str(), P(x) * P(x_m1), irred);
  std::vector<Z> vf(M), vg(M);
  for (int m = 0; m < M; ++m) vf[m] = m + 1 + m * m, vg[m] = m + 1 - m * m;
  const P f(vf), g(vg);
  TEST((p + "products commute").c_str(), f * g, g * f);
  TEST((p + "products distribute").c_str(), f * (g + irred), f * g + f * irred);
  P t = Z(1);
  unsigned order = 1;
  do {
    t *= irred;
  } while (t != Z(1) && ++order < P::cardinality());
  TEST((p + "multiplicative order").c_str(), irred.multiplicative_order(), order);
  TEST((p + "is_field").c_str(), P::is_field(), is_field);
  TEST((p + "a field iff the order is N^M - 1").c_str(), order + 1 == P::cardinality(), is_field);
  std::vector<Z> ends(M, Z(0));
  ends[0] = 1, ends[M - 1] = 1;
  std::ostringstream text;
  text << P(ends);
  TEST((p + "printed as upstream").c_str(), text.str(), M == 2 ? std::string("1+X") : "1+X^" + std::to_string(M - 1));
}
}  // namespace

static void test_finite() {
  check_finite_int<2>();
  check_finite_int<3>();
  check_finite_int<4>();
  TEST("2 * 2 = 0 mod 4", vnl_finite_int<4>(2) * vnl_finite_int<4>(2), 0);
  check_finite_int<5>();
  check_finite_int<6>();
  TEST("2 * 3 = 0 mod 6", vnl_finite_int<6>(2) * 3, 0);
  check_finite_int<7>();
  check_finite_int<8>();
  check_finite_int<9>();
  check_finite_int<10>();
  check_finite_int<17>();
  check_finite_int<31>();
  check_finite_int<100>();
  TEST("25 * 20 = 0 mod 100", 25 * vnl_finite_int<100>(20), 0);
  check_finite_int<243>();
  check_finite_int<256>();
  check_finite_int<432>();
  TEST("180 * 12 = 0 mod 432", vnl_finite_int<432>(180) * 12, 0);
  check_finite_int<257>();
  check_finite_int<0x10001>();

  using Z7 = vnl_finite_int<7>;
  using Z12 = vnl_finite_int<12>;
  TEST("cardinality", Z7::cardinality(), 7u);
  TEST("1 / 3 = 5 mod 7", Z7(1) / Z7(3), Z7(5));
  TEST("4 is a zero divisor mod 12", Z12(4).is_zero_divisor(), true);
  TEST("0 is a zero divisor (not a unit), as upstream", Z12(0).is_zero_divisor(), true);
  TEST("5 is a unit mod 12, no zero divisor", Z12(5).is_zero_divisor(), false);
  TEST("Z_12 is not a field", Z12::is_field(), false);
  TEST("totient(12) = 4", Z12::totient(), 4u);
  TEST("additive order of 4 mod 12 is 3", Z12(4).additive_order(), 3u);
  TEST("a zero divisor has no multiplicative order", Z12(6).multiplicative_order(), -1);
  TEST("3 generates the units mod 7", Z7::smallest_generator(), Z7(3));
  TEST("pow(-1) is the inverse", Z7(3).pow(-1), Z7(5));
  TEST("12 = 2 * 2 * 3", Z12::decompose() == std::vector<unsigned>({2, 2, 3}), true);
  TEST("gcd(12, 18) = 6", Z12::gcd(12, 18), 6u);

  check_finite_poly<2, 5>("1 0 1 0 0 1", true);  // GF(32)
  check_finite_poly<3, 3>("1 2 0 1", true);      // GF(27)
  check_finite_poly<3, 3>("1 1 0 1", false);     // reducible: not a field (the modulus is reset)
  check_finite_poly<6, 2>("1 0 1", false);       // Z_6 is no field
  TEST("additive order of 2 + 3X over Z_6",
       (vnl_finite_int_poly<6, 2>(std::vector<vnl_finite_int<6>>{2, 3})).additive_order(), 6u);
}

TESTMAIN(test_finite)
