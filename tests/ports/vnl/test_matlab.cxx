// SPDX-License-Identifier: BSD-3-Clause
// vnl_matlab_print as upstream's test_matlab.cxx (its printing part): vectors and matrices,
// dynamic, fixed, _ref and diagonal, named and unnamed, in each format, through the stream
// proxy of vnl_matlab_print2.h and with the process-wide default format pushed and popped;
// complex and integer scalars; for double, float and the configured real. Upstream's test
// also writes and reads .mat files, which this port leaves out (MATLAB file I/O).
#include <complex>
#include <sstream>
#include <string>

#include "testlib/testlib_test.h"
#include "vnl/vnl_diag_matrix.h"
#include "vnl/vnl_matlab_print.h"
#include "vnl/vnl_matlab_print2.h"
#include "vnl_test_types.h"

namespace {
template <class T>
struct check_print {
  static std::string text_of(const vnl_vector<T>& v, const char* name, vnl_matlab_print_format f) {
    std::ostringstream s;
    vnl_matlab_print(s, v, name, f);
    return s.str();
  }
  static void run(const std::string& scalar) {
    const std::string p = scalar + ": ";
    const bool narrow = std::is_same<T, float>::value;  // floats print narrower, as upstream
    const vnl_vector<T> v{T(0), T(1) / T(2), T(-1) / T(4)};
    const std::string v_short = narrow ? "     0  0.500 -0.250 " : "       0   0.5000  -0.2500 ";
    TEST((p + "unnamed vector, short").c_str(), text_of(v, nullptr, vnl_matlab_print_format_short), v_short);
    TEST((p + "named vector").c_str(), text_of(v, "v", vnl_matlab_print_format_short), "v = [ " + v_short + " ]\n");
    const std::string v_long_e = narrow ? "0.0000000e+00 5.0000000e-01 -2.5000000e-01 "
                                        : "0.00000000000000e+00 5.00000000000000e-01 -2.50000000000000e-01 ";
    TEST((p + "long e format").c_str(), text_of(v, nullptr, vnl_matlab_print_format_long_e), v_long_e);
    vnl_matlab_print_format_push(vnl_matlab_print_format_long_e);
    TEST((p + "pushed default format").c_str(), text_of(v, nullptr, vnl_matlab_print_format_default), v_long_e);
    vnl_matlab_print_format_pop();
    TEST((p + "popped back to short").c_str(), text_of(v, nullptr, vnl_matlab_print_format_default), v_short);

    vnl_matrix<T> M(2, 2, T(0));
    M(0, 1) = T(1) / T(2), M(1, 0) = T(2);
    const std::string row0 = narrow ? "     0  0.500 " : "       0   0.5000 ";
    const std::string row1 = narrow ? " 2.000      0 " : "  2.0000        0 ";
    const std::string named = "M = [ ...\n" + row0 + "\n" + row1 + " ]\n";
    std::ostringstream m, mf, mr, unnamed, proxy;
    vnl_matlab_print(m, M, "M", vnl_matlab_print_format_short);
    TEST((p + "named matrix").c_str(), m.str(), named);
    vnl_matlab_print(unnamed, M, nullptr, vnl_matlab_print_format_short);
    TEST((p + "unnamed matrix, a row per line").c_str(), unnamed.str(), row0 + "\n" + row1 + "\n");
    vnl_matlab_print(mf, vnl_matrix_fixed<T, 2, 2>(M), "M", vnl_matlab_print_format_short);
    TEST((p + "fixed matrix prints the same").c_str(), mf.str(), named);
    vnl_matlab_print(mr, vnl_matrix_ref<T>(2, 2, M.data_block()), "M", vnl_matlab_print_format_short);
    TEST((p + "matrix_ref prints the same").c_str(), mr.str(), named);
    proxy << vnl_matlab_print(M, "M", vnl_matlab_print_format_short);
    TEST((p + "through the stream proxy").c_str(), proxy.str(), named);
    std::ostringstream d, vf, empty;
    vnl_matlab_print(d, vnl_diag_matrix<T>(v), "D", vnl_matlab_print_format_short);
    TEST((p + "diagonal matrix").c_str(), d.str(), "D = diag([ " + v_short + " ])\n");
    vnl_matlab_print(vf, vnl_vector_fixed<T, 3>(v.data_block()), "v", vnl_matlab_print_format_short);
    TEST((p + "fixed vector").c_str(), vf.str(), "v = [ " + v_short + " ]\n");
    vnl_matlab_print(empty, vnl_matrix<T>(), "E");
    TEST((p + "empty named matrix").c_str(), empty.str(), "E = [ ...\n];\n");
  }
};
}  // namespace

static void test_matlab() {
  TEST("the default format starts short", vnl_matlab_print_format_top(), vnl_matlab_print_format_short);
  for_each_test_scalar<check_print>();
  const vnl_matlab_print_format old = vnl_matlab_print_format_set(vnl_matlab_print_format_long);
  std::ostringstream s;
  vnl_matlab_print_scalar(s, 0.25);
  TEST("set() changes the default, long format", s.str(), " 0.2500000000000 ");
  TEST("set() returns the old default", vnl_matlab_print_format_set(old), vnl_matlab_print_format_long);
  std::ostringstream c, i;
  vnl_matlab_print_scalar(c, std::complex<double>(1.5, -2), vnl_matlab_print_format_short);
  TEST("complex, short", c.str(), "  1.5000 - 2.0000i ");
  vnl_matlab_print_scalar(i, 42);
  TEST("int", i.str(), "  42 ");
  char tiny[6];
  vnl_matlab_print_scalar(123.456, tiny, sizeof tiny, vnl_matlab_print_format_short);
  TEST("a short buffer is filled and terminated", std::string(tiny), "123.4");
}

TESTMAIN(test_matlab)
