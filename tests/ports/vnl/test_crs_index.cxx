// SPDX-License-Identifier: BSD-3-Clause
// vnl_crs_index as upstream's test_crs_index.cxx: indices of the nonzeros of a mask, row by
// row, -1 elsewhere, and the sparse rows and columns.
#include <vector>

#include "testlib/testlib_test.h"
#include "vnl/vnl_crs_index.h"

static void test_crs_index() {
  // [1 0 1 0]
  // [0 0 0 0]
  // [1 1 0 1]
  const std::vector<std::vector<bool>> mask = {
      {true, false, true, false}, {false, false, false, false}, {true, true, false, true}};
  const vnl_crs_index crs(mask);
  TEST("num_rows", crs.num_rows(), 3);
  TEST("num_cols", crs.num_cols(), 4);
  TEST("num_non_zero", crs.num_non_zero(), 5);
  TEST("(0,0) is nonzero 0", crs(0, 0), 0);
  TEST("(0,2) is nonzero 1", crs(0, 2), 1);
  TEST("(2,3) is nonzero 4", crs(2, 3), 4);
  TEST("(0,1) is zero", crs(0, 1), -1);
  TEST("an empty row has no nonzeros", crs(1, 2), -1);
  const vnl_crs_index::sparse_vector row = crs.sparse_row(2);
  TEST("sparse_row(2) has 3 entries", row.size(), 3u);
  TEST("sparse_row(2)[1] is (index 3, column 1)", row[1].first == 3 && row[1].second == 1, true);
  const vnl_crs_index::sparse_vector col = crs.sparse_col(0);
  TEST("sparse_col(0) is (0, row 0), (2, row 2)", col.size() == 2 && col[1].first == 2 && col[1].second == 2, true);
}

TESTMAIN(test_crs_index)
