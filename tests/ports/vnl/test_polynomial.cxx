// SPDX-License-Identifier: BSD-3-Clause
// vnl_polynomial<T> as upstream's test_polynomial.cxx: printing, negation, sums, products,
// quotient and remainder, derivative, primitive and evaluation.
#include <sstream>
#include <string>
#include <type_traits>

#include "testlib/testlib_test.h"
#include "vnl/vnl_polynomial.h"
#include "vnl_test_types.h"

namespace {

template <class T>
std::string printed(const vnl_polynomial<T>& p) {
  std::ostringstream out;
  p.print(out);
  return out.str();
}

template <class T>
struct CheckPolynomial {
  static void run(const std::string& type) {
    const std::string in = " (" + type + ")";
    const T a1[] = {T(1), T(2), T(3), T(4)};  // X^3 + 2 X^2 + 3 X + 4, highest first
    const vnl_polynomial<T> f1(a1, 4);
    const vnl_polynomial<T> f2(std::vector<T>{T(1), T(1)});  // 1 + X, lowest first
    TEST("f1 prints as X^3 +2 X^2 +3 X +4" + in, printed(f1), std::string(" X^3 +2 X^2 +3 X +4"));
    TEST("degree" + in, f1.degree() == 3 && f2.degree() == 1 && vnl_polynomial<T>().degree() == -1, true);
    TEST("f1[0] is the constant term" + in, f1[0] == T(4), true);
    TEST("-f1(x)" + in, (-f1).evaluate(T(1)) == T(-10), true);
    TEST("f1+f2" + in, (f1 + f2).evaluate(T(2)) == T(26 + 3), true);
    TEST("f2+f1 = f1+f2" + in, f2 + f1 == f1 + f2, true);
    TEST("f1-f2" + in, (f1 - f2).evaluate(T(2)) == T(26 - 3), true);
    TEST("f1-f1 is the zero polynomial" + in, (f1 - f1).degree(), -1);
    TEST("f1*f2 degree" + in, (f1 * f2).degree(), 4);
    TEST("f1*f2 at 2" + in, (f1 * f2).evaluate(T(2)) == T(26 * 3), true);
    // f1 = (X + 1)(X^2 + X + 2) + 2.
    TEST("f1 / f2 is X^2 + X + 2" + in, f1 / f2 == vnl_polynomial<T>(std::vector<T>{T(2), T(1), T(1)}), true);
    TEST("f1 % f2 is 2" + in, f1 % f2 == vnl_polynomial<T>(std::vector<T>{T(2)}), true);
    TEST("derivative" + in, f1.derivative() == vnl_polynomial<T>(std::vector<T>{T(3), T(4), T(3)}), true);
    TEST("devaluate" + in, f1.devaluate(T(1)) == T(10), true);
    TEST("primitive of the derivative is f1 - 4" + in, f1.derivative().primitive() == f1 - vnl_polynomial<T>(std::vector<T>{T(4)}),
         true);
    if constexpr (!std::is_integral_v<T>) {  // an integer primitive truncates 1/2 X^2
      TEST_NEAR("integral of f2 over [0, 2]" + in, f2.evaluate_integral(T(0), T(2)), 4.0, ulps<T>(8));
    }
    TEST("the zero polynomial prints as 0" + in, printed(vnl_polynomial<T>()), std::string(" 0"));
    TEST("-X^2 + 1 prints its signs" + in, printed(vnl_polynomial<T>(std::vector<T>{T(1), T(0), T(-1)})),
         std::string(" -X^2 +1"));
  }
};

void test_polynomial() {
  CheckPolynomial<int>::run("int");
  CheckPolynomial<long>::run("long");
  for_each_test_scalar<CheckPolynomial>();
}

}  // namespace

TESTMAIN(test_polynomial)
