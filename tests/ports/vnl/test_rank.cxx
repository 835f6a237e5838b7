// SPDX-License-Identifier: BSD-3-Clause
// vnl_rank as upstream's algo test_rank.cxx: ranks of integer matrices of full and deficient
// rank, by rows and by columns, and the reduced forms.
#include "testlib/testlib_test.h"
#include "vnl/vnl_rank.h"

static void test_rank() {
  const vnl_matrix<int> id(4, 4, vnl_matrix_identity);
  TEST("rank of I4", vnl_rank(id), 4u);
  const vnl_matrix<int> m{{1, 2, 3}, {4, 5, 6}, {7, 8, 9}};
  TEST("rank of [1..9] is 2", vnl_rank(m), 2u);
  TEST("by rows", vnl_rank(m, vnl_rank_row), 2u);
  TEST("by columns", vnl_rank(m, vnl_rank_column), 2u);
  const vnl_matrix<int> wide{{2, 4, 6, 8}, {1, 2, 3, 4}};
  TEST("proportional rows: rank 1", vnl_rank(wide), 1u);
  TEST("zero matrix: rank 0", vnl_rank(vnl_matrix<int>(3, 2, 0)), 0u);
  const vnl_matrix<int> big{{3, 1, 4, 1}, {5, 9, 2, 6}, {5, 3, 5, 8}, {9, 7, 9, 3}, {2, 3, 8, 4}};
  TEST("a 5x4 integer matrix of full column rank", vnl_rank(big), 4u);
  const vnl_matrix<int> reduced = vnl_rank_row_reduce(m);
  TEST("row reduction zeroes the last row of [1..9]", reduced(2, 0) == 0 && reduced(2, 1) == 0 && reduced(2, 2) == 0,
       true);
  TEST("column reduction is the transpose's row reduction",
       vnl_rank_column_reduce(m) == vnl_rank_row_reduce(m.transpose()).transpose(), true);
  const vnl_matrix<double> d{{1, 0.5}, {2, 1}};
  TEST("a double matrix with an exact dependency: rank 1", vnl_rank(d), 1u);
}

TESTMAIN(test_rank)
