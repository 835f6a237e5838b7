// SPDX-License-Identifier: BSD-3-Clause
// vnl_na as upstream's test_na.cxx: NA is a NaN told apart from other NaNs, survives float
// conversion, converts from NaN, and reads and prints as "NA".
#include <cmath>
#include <sstream>
#include <string>

#include "testlib/testlib_test.h"
#include "vnl/vnl_c_na_vector.h"
#include "vnl/vnl_na.h"

static void test_na() {
  const double na = vnl_na(double());
  TEST("NA is a NaN", std::isnan(na), true);
  TEST("NA is NA", vnl_na_isna(na), true);
  TEST("an ordinary NaN is not NA", vnl_na_isna(std::nan("")), false);
  TEST("a number is not NA", vnl_na_isna(1.0), false);
  TEST("float NA is NA", vnl_na_isna(vnl_na(float())), true);
  TEST("nan_to_na turns NaN into NA", vnl_na_isna(vnl_na_nan_to_na(std::nan(""))), true);
  TEST("nan_to_na keeps numbers", vnl_na_nan_to_na(2.5), 2.5);
  std::istringstream in("1.5 NA -2");
  double a = 0, b = 0, c = 0;
  in >> vnl_na_stream(a) >> vnl_na_stream(b) >> vnl_na_stream(c);
  TEST("reads a number, NA, a number", a == 1.5 && vnl_na_isna(b) && c == -2, true);
  std::istringstream glued("NA1.0NANA");
  double d = 0, e = 0, f = 0;
  vnl_na_extract(glued, d);
  vnl_na_extract(glued, e);
  vnl_na_extract(glued, f);
  TEST("NA glued to a number or to NA: two characters each", vnl_na_isna(d) && e == 1.0 && vnl_na_isna(f), true);
  std::ostringstream out;
  out << vnl_na_stream(na) << ' ' << vnl_na_stream(3.0);
  TEST("prints NA and numbers", out.str(), std::string("NA 3"));
  const double values[] = {1, na, 3, na};
  TEST("vnl_c_na_vector::sum skips NA", vnl_c_na_vector<double>::sum(values, 4), 4.0);
  TEST("vnl_c_na_vector::mean counts only the others", vnl_c_na_vector<double>::mean(values, 4), 2.0);
  TEST("vnl_c_na_vector::two_nrm2", vnl_c_na_vector<double>::two_nrm2(values, 4), 10.0);
  TEST("the mean of only NAs is NA", vnl_na_isna(vnl_c_na_vector<double>::mean(values + 1, 1)), true);
}

TESTMAIN(test_na)
