// SPDX-License-Identifier: BSD-3-Clause
/// The checks upstream's test_bignum.cxx and test_decnum.cxx share, for either number type:
/// sums and products with zero, 10^18 and the infinities, factorials and binomials, large
/// quotients, increments across a 16-bit digit, and the order of an ascending list.
#pragma once

#include <sstream>
#include <string>

#include "testlib/testlib_test.h"

namespace big_number_checks {
/// The number operator>> reads from `text`.
template <class Num>
Num read(const std::string& text) {
  std::istringstream is(text);
  Num b;
  is >> b;
  return b;
}

template <class Num>
Num factorial(long n) {
  return n <= 1 ? Num(1L) : factorial<Num>(n - 1) * Num(n);
}

template <class Num>
Num binomial(long n, long k) {
  Num c(1L);
  if (k >= n || k <= 0) return c;
  for (long i = n; i > n - k; --i) c *= Num(i);
  return c /= factorial<Num>(k);
}

/// How many of ==, !=, <, >, <=, >= disagree with the positions in an ascending list.
template <class Num, int n>
int order_errors(const Num (&values)[n]) {
  int errors = 0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const Num &a = values[i], &b = values[j];
      errors += (a == b) != (i == j) || (a != b) != (i != j) || (a < b) != (i < j) || (a > b) != (i > j) ||
                (a <= b) != (i <= j) || (a >= b) != (i >= j);
    }
  }
  return errors;
}

template <class Num>
void check_sums_with_infinities() {
  const Num b0(0L), b1000(1000L), b1000000(1000000L), zillion("1000000000000000000");
  const Num p_inf("+Inf"), m_inf("-Inf");
  TEST("-0 == 0", -b0, b0);
  TEST("-+Inf == -Inf", -p_inf, m_inf);
  TEST("-b1000 == -1 * b1000", -b1000, Num(-1L) * b1000);
  TEST("0 + 1000", b0 + b1000, b1000);
  TEST("-1000 + -1000", -b1000 + (-b1000), Num(2L) * (-b1000));
  TEST("10^6 - 10^6", b1000000 + (-b1000000), b0);
  TEST("zillion - zillion", zillion + (-zillion), b0);
  TEST("zillion + 1000", zillion + b1000, b1000000 * b1000000 * b1000000 + b1000);
  TEST("zillion + +Inf", zillion + p_inf, p_inf);
  TEST("-Inf + zillion", m_inf + zillion, m_inf);
  TEST("-1000 - -zillion", -b1000 - (-zillion), zillion - b1000);
  TEST("-10^6 - 10^6", -b1000000 - b1000000, -Num(2L) * b1000000);
  TEST("-zillion - 1000", -zillion - b1000, -b1000000 * b1000000 * b1000000 - b1000);
  TEST("zillion - +Inf", zillion - p_inf, m_inf);
  const Num b2 = "4294967295", b3 = "12345e30";
  TEST("(b2 + b3) - b2 == b3", (b2 + b3) - b2 == b3, true);
  TEST("(b2 + b3) - b3 == b2", (b2 + b3) - b3 == b2, true);
}

template <class Num>
void check_products() {
  const Num b0(0L), b1000(1000L), b1000000(1000000L), zillion("1000000000000000000");
  const Num p_inf("+Inf"), m_inf("-Inf");
  TEST("0 * 1000", b0 * b1000, b0);
  TEST("1000 * 1000", b1000 * b1000, b1000000);
  TEST("-(10^6)^3 == -zillion", -b1000000 * b1000000 * b1000000, -zillion);
  TEST("zillion * -1000 == 1000 * -zillion", zillion * -b1000, b1000 * -zillion);
  TEST("+Inf * 1000", p_inf * b1000, p_inf);
  TEST("-Inf * 1000", m_inf * b1000, m_inf);
  TEST("+Inf * -1000", p_inf * -b1000, m_inf);
  TEST("10!", factorial<Num>(10), Num(3628800L));
  TEST("15!", factorial<Num>(15), Num("1307674368000"));
  TEST("44!", factorial<Num>(44), Num("2658271574788448768043625811014615890319638528000000000"));
}

template <class Num>
void check_large_division() {
  const char* pairs[][2] = {{"10000000", "10000001"}, {"111111", "111111"}, {"98789", "98789"}};
  for (const auto& pair : pairs) {
    const Num a(pair[0]), b(pair[1]);
    TEST((std::string("(") + pair[0] + " * " + pair[1] + ") / " + pair[1]).c_str(), (a * b) / b, a);
  }
  const Num a("1e100"), b("1e200");
  TEST("1e200 / 1e100", b / a, a);
  TEST("1e200 / -1e100", b / -a, -a);
  TEST("-1e200 / -1e100", -b / -a, a);
  TEST("1e200 % 1e100", b % a, Num(0L));
  TEST("16 choose 8", binomial<Num>(16, 8), Num(12870L));
  TEST("20 choose 10", binomial<Num>(20, 10), Num(184756L));
  TEST("100 choose 44", binomial<Num>(100, 44), Num("49378235797073715747364762200"));
  const Num b2 = "4294967295", b3 = "12345e30";
  TEST("(b2 * b3) / b3 == b2", (b2 * b3) / b3, b2);
  TEST("(b2 * b3) / b2 == b3", (b2 * b3) / b2, b3);
  TEST("(b3 / b2) * b2 + b3 % b2 == b3", (b3 / b2) * b2 + b3 % b2, b3);
}

template <class Num>
void check_increments() {
  Num b;
  TEST("++ twice", (++b, ++b), Num(2L));
  TEST("-- four times", (--b, --b, --b, --b), Num(-2L));
  TEST("postfix ++ gives the old value", b++ == Num(-2L) && b == Num(-1L), true);
  Num b4("65534");
  TEST("65534 + 3", (++b4, ++b4, ++b4), Num(65537L));
  TEST("and back", (--b4, --b4, --b4), Num(65534L));
  Num b5("-65534");
  TEST("-65534 - 3", (--b5, --b5, --b5), Num(-65537L));
  TEST("and back", (++b5, ++b5, ++b5), Num(-65534L));
}
}  // namespace big_number_checks
