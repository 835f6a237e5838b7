// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/vnl_error.h"

#include <cstdio>
#include <string>

#include "vcl/vcl_compiler.h"

inline namespace edgetrack_ports {

namespace {
[[noreturn]] void fail(const std::string& message) {
  std::fprintf(stderr, "vnl: %s\n", message.c_str());
  vcl_abort(message.c_str());
}
}  // namespace

void vnl_error_vector_index(const char* fcn, int index) {
  fail(std::string(fcn) + ": index " + std::to_string(index) + " out of range");
}
void vnl_error_vector_dimension(const char* fcn, int l1, int l2) {
  fail(std::string(fcn) + ": vectors of sizes " + std::to_string(l1) + " and " + std::to_string(l2));
}
void vnl_error_vector_va_arg(int n) { fail("vector given " + std::to_string(n) + " values of the wrong type"); }
void vnl_error_matrix_row_index(const char* fcn, unsigned r) {
  fail(std::string(fcn) + ": row " + std::to_string(r) + " out of range");
}
void vnl_error_matrix_col_index(const char* fcn, unsigned c) {
  fail(std::string(fcn) + ": column " + std::to_string(c) + " out of range");
}
void vnl_error_matrix_dimension(const char* fcn, int r1, int c1, int r2, int c2) {
  fail(std::string(fcn) + ": matrices of sizes " + std::to_string(r1) + "x" + std::to_string(c1) + " and " +
       std::to_string(r2) + "x" + std::to_string(c2));
}
void vnl_error_matrix_nonsquare(const char* fcn) { fail(std::string(fcn) + ": matrix is not square"); }
void vnl_error_matrix_va_arg(int n) { fail("matrix given " + std::to_string(n) + " values of the wrong type"); }

}  // inline namespace edgetrack_ports
