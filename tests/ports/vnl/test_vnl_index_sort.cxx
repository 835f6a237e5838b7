// SPDX-License-Identifier: BSD-3-Clause
// vnl_index_sort as upstream's test_vnl_index_sort.cxx: sorted values with their original
// indices, in place, and by row and by column of a matrix.
#include "testlib/testlib_test.h"
#include "vnl/vnl_index_sort.h"

static void test_vnl_index_sort() {
  using sorter = vnl_index_sort<double, int>;
  sorter sort;
  const vnl_vector<double> values{3.5, -1.0, 2.0, -1.0, 10.0};
  vnl_vector<double> sorted;
  vnl_vector<int> indices;
  sort.vector_sort(values, sorted, indices);
  TEST("sorted ascending", sorted[0] == -1.0 && sorted[4] == 10.0 && sorted[2] == 2.0, true);
  TEST("indices give the original places (stable on ties)", indices[0] == 1 && indices[1] == 3 && indices[4] == 4,
       true);
  vnl_vector<double> in_place(values);
  sort.vector_sort_in_place(in_place, indices);
  TEST("vector_sort_in_place", in_place == sorted, true);
  const vnl_matrix<double> m{{3, 1, 2}, {0, 9, -4}};
  vnl_matrix<double> sm;
  vnl_matrix<int> im;
  sort.matrix_sort(sorter::ByRow, m, sm, im);
  TEST("ByRow sorts each row", sm(0, 0) == 1 && sm(1, 0) == -4 && im(1, 0) == 2, true);
  sort.matrix_sort(sorter::ByColumn, m, sm, im);
  TEST("ByColumn sorts each column", sm(0, 1) == 1 && sm(1, 2) == 2 && im(0, 2) == 1, true);
}

TESTMAIN(test_vnl_index_sort)
