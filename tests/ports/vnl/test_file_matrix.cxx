// SPDX-License-Identifier: BSD-3-Clause
// vnl_file_matrix as upstream's test_file_matrix.cxx: a 3x3 matrix read from the source tree
// (found through testlib_root_dir), its values, arithmetic on it, and a missing file.
#include <string>

#include "testlib/testlib_root_dir.h"
#include "testlib/testlib_test.h"
#include "vnl/vnl_file_matrix.h"
#include "vnl/vnl_file_vector.h"
#include "vnl/vnl_int_matrix.h"

static void test_file_matrix() {
  const std::string path = testlib_root_dir() + "/tests/ports/vnl/data_3x3_matrix";
  vnl_file_matrix<double> h(path.c_str());
  TEST("the file was read", static_cast<bool>(h), true);
  TEST("file_matrix 3x3: rows", h.rows(), 3u);
  TEST("file_matrix 3x3: cols", h.cols(), 3u);
  TEST_NEAR("data(1,2)", h(1, 2), 7.5, 1e-15);
  h /= h[0][0];
  TEST_NEAR("divided by h(0,0)", h(0, 0), 1.0, 1e-15);
  TEST_NEAR("divided by h(0,0): (2,0)", h(2, 0), -1.2, 1e-15);
  const vnl_file_vector<float> v(path.c_str());
  TEST("vnl_file_vector reads all 9 values", v.size(), 9u);
  const vnl_int_matrix rounded(vnl_matrix<double>(vnl_file_matrix<double>(path.c_str())));
  TEST("vnl_int_matrix rounds to nearest", rounded(0, 0) == 3 && rounded(2, 1) == 2, true);
  const vnl_file_matrix<double> missing("/nonexistent/vnl_file_matrix_test");
  TEST("a missing file converts to false", !missing, true);
}

TESTMAIN(test_file_matrix)
