// SPDX-License-Identifier: BSD-3-Clause
// vnl_matlab_print as upstream's test_matlab.cxx (its printing part): vectors and matrices,
// dynamic, fixed, _ref and diagonal, named and unnamed, in each format, through the stream
// proxy of vnl_matlab_print2.h and with the process-wide default format pushed and popped;
// complex and integer scalars; for double, float and the configured real. Then, as upstream,
// a float vector and a double matrix written as .mat data and read back (header fields, name,
// values), also from data in the other byte order; and a file of vnl_matlab_filewrite.
#include <complex>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "testlib/testlib_test.h"
#include "vnl/vnl_diag_matrix.h"
#include "vnl/vnl_matlab_filewrite.h"
#include "vnl/vnl_matlab_header.h"
#include "vnl/vnl_matlab_print.h"
#include "vnl/vnl_matlab_print2.h"
#include "vnl/vnl_matlab_read.h"
#include "vnl/vnl_matlab_write.h"
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
/// A float column in the byte order opposite to this machine's (upstream's matlab_write_swapped).
void write_swapped(std::ostream& f, const float* array, unsigned size, const char* name) {
  const bool big_endian_host = __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__;
  vnl_matlab_header hdr;
  hdr.type = (big_endian_host ? vnl_matlab_header::vnl_LITTLE_ENDIAN : vnl_matlab_header::vnl_BIG_ENDIAN) +
             vnl_matlab_header::vnl_COLUMN_WISE + vnl_matlab_header::vnl_SINGLE_PRECISION;
  hdr.rows = static_cast<std::int32_t>(size), hdr.cols = 1, hdr.imag = 0;
  hdr.namlen = static_cast<std::int32_t>(std::strlen(name) + 1);
  for (std::int32_t* field : {&hdr.type, &hdr.rows, &hdr.cols, &hdr.imag, &hdr.namlen}) byteswap::swap32(field);
  f.write(reinterpret_cast<const char*>(&hdr), sizeof hdr);
  f.write(name, static_cast<std::streamsize>(std::strlen(name) + 1));
  for (unsigned i = 0; i < size; ++i) {
    float value = array[i];
    byteswap::swap32(&value);
    f.write(reinterpret_cast<const char*>(&value), sizeof value);
  }
}

void check_vector_header(const std::string& p, vnl_matlab_readhdr& h, const vnl_vector<float>& v) {
  TEST((p + "header read").c_str(), bool(h), true);
  TEST((p + "single, real, a column named v").c_str(),
       h.is_single() && !h.is_complex() && h.rows() == long(v.size()) && h.cols() == 1 &&
           std::strcmp(h.name(), "v") == 0,
       true);
  vnl_vector<float> read_back(v.size());
  TEST((p + "values read back").c_str(), h.read_data(read_back.data_block()) && read_back == v, true);
}

void check_mat_files() {
  vnl_vector<float> v(4);
  for (unsigned i = 0; i < v.size(); ++i) v[i] = 0.1f * float(i);
  vnl_matrix<double> M(3, 4);
  for (unsigned i = 0; i < M.rows(); ++i) {
    for (unsigned j = 0; j < M.cols(); ++j) M(i, j) = 0.1 * i * j;
  }
  const auto binary = std::ios::in | std::ios::out | std::ios::binary;
  std::stringstream file(binary), swapped(binary);
  vnl_matlab_write(file, v.data_block(), 4, "v");
  vnl_matlab_write(file, M.data_array(), 3, 4, "M");
  write_swapped(swapped, v.data_block(), 4, "v");

  vnl_matlab_readhdr vh(file);
  check_vector_header("native: ", vh, v);
  vnl_matlab_readhdr sh(swapped);
  check_vector_header("other byte order: ", sh, v);
  vnl_matlab_readhdr Mh(file);
  TEST("matrix header: double, row-wise, 3 x 4, named M",
       bool(Mh) && !Mh.is_single() && Mh.is_rowwise() && !Mh.is_complex() && Mh.rows() == 3 && Mh.cols() == 4 &&
           std::strcmp(Mh.name(), "M") == 0,
       true);
  vnl_matrix<float> wrong(3, 4);
  TEST("reading doubles into floats is refused", Mh.read_data(wrong.data_array()), false);
  vnl_matrix<double> M_(3, 4);
  TEST("matrix read back", Mh.read_data(M_.data_array()) && M_ == M, true);

  std::stringstream again(binary);
  const std::complex<double> z(1.5, -2);
  vnl_matlab_write(again, z, "z");
  vnl_matlab_write(again, M.data_array(), 3, 4, "M");
  vnl_matlab_readhdr zh(again);
  std::complex<double> z_;
  TEST("complex scalar read back", zh.is_complex() && zh.read_data(z_) && z_ == z, true);
  vnl_matrix<double> M2;
  TEST("vnl_matlab_read_or_die reads a matrix and sizes it", vnl_matlab_read_or_die(again, M2, "M") && M2 == M, true);
  TEST("and is false at the end of the data", vnl_matlab_read_or_die(again, M2), false);

  const char* name = "test_matlab_filewrite.mat";
  {
    vnl_matlab_filewrite out(name, "x");
    out.write(2.5);
    out.write(M, "M");
    out.write(vnl_vector<double>(2, 7.0));
  }
  std::ifstream in(name, std::ios::binary);
  vnl_matlab_readhdr h0(in);
  double x0 = 0;
  TEST("filewrite: a scalar named x0", std::strcmp(h0.name(), "x0") == 0 && h0.read_data(x0) && x0 == 2.5, true);
  h0.read_next();
  TEST("filewrite: then M (skipped)", std::strcmp(h0.name(), "M") == 0, true);
  h0.read_next();
  vnl_vector<double> x1(2);
  TEST("filewrite: then x1", std::strcmp(h0.name(), "x1") == 0 && h0.read_data(x1.data_block()) && x1[1] == 7.0, true);
  in.close();
  std::remove(name);
}
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
  check_mat_files();
}

TESTMAIN(test_matlab)
