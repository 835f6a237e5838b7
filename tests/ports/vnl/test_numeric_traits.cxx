// SPDX-License-Identifier: BSD-3-Clause
// vnl_numeric_traits gives upstream's zero, one, maxval and the abs/double/real types
// (upstream's test_numeric_traits.cxx), and ours for the fixed-point scalars.
#include <complex>
#include <limits>
#include <type_traits>

#include "real/real.h"
#include "testlib/testlib_test.h"
#include "vnl/vnl_numeric_traits.h"

static void test_numeric_traits() {
  TEST("int zero", vnl_numeric_traits<int>::zero, 0);
  TEST("int one", vnl_numeric_traits<int>::one, 1);
  TEST("int maxval", vnl_numeric_traits<int>::maxval, std::numeric_limits<int>::max());
  TEST("unsigned char maxval", vnl_numeric_traits<unsigned char>::maxval, 255);
  TEST("short maxval", vnl_numeric_traits<short>::maxval, 32767);
  TEST("double maxval", vnl_numeric_traits<double>::maxval, std::numeric_limits<double>::max());
  TEST("float one", vnl_numeric_traits<float>::one, 1.0f);
  TEST("bool maxval", vnl_numeric_traits<bool>::maxval, true);
  TEST("int abs_t is unsigned int", (std::is_same_v<vnl_numeric_traits<int>::abs_t, unsigned int>), true);
  TEST("int real_t is double", (std::is_same_v<vnl_numeric_traits<int>::real_t, double>), true);
  TEST("float real_t is double", (std::is_same_v<vnl_numeric_traits<float>::real_t, double>), true);
  TEST("float double_t is double", (std::is_same_v<vnl_numeric_traits<float>::double_t, double>), true);
  TEST("unsigned char double_t is unsigned short",
       (std::is_same_v<vnl_numeric_traits<unsigned char>::double_t, unsigned short>), true);
  TEST("complex<double> abs_t is double", (std::is_same_v<vnl_numeric_traits<std::complex<double>>::abs_t, double>),
       true);
  TEST("complex<float> one", vnl_numeric_traits<std::complex<float>>::one, std::complex<float>(1, 0));
  TEST("const int shares int's traits", vnl_numeric_traits<const int>::maxval, std::numeric_limits<int>::max());
  using fixed = fixedpoint::s40_23;
  TEST("fixed point is its own abs_t", (std::is_same_v<vnl_numeric_traits<fixed>::abs_t, fixed>), true);
  TEST("fixed point is its own real_t (vnl stays in fixed point)",
       (std::is_same_v<vnl_numeric_traits<fixed>::real_t, fixed>), true);
  TEST("fixed point maxval is numeric_limits max", vnl_numeric_traits<fixed>::maxval == std::numeric_limits<fixed>::max(),
       true);
  TEST("real's traits exist (the configured scalar)", vnl_numeric_traits<real>::one == real(1), true);
}

TESTMAIN(test_numeric_traits)
