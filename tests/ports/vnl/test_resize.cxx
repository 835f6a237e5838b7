// SPDX-License-Identifier: BSD-3-Clause
// set_size as upstream's test_resize.cxx: vectors and matrices take their new size (and
// ours are zero afterwards), and fill works after resizing; a view cannot resize.
#include "testlib/testlib_test.h"
#include "vnl/vnl_matrix.h"
#include "vnl/vnl_vector.h"
#include "vnl/vnl_vector_ref.h"

static void test_resize() {
  vnl_vector<double> v(3, 2.0);
  v.set_size(5);
  TEST("vector size", v.size(), 5u);
  TEST("a resized vector is zero", v.is_zero(), true);
  v.fill(2);
  TEST("fill 2", v.sum(), 10.0);
  vnl_matrix<double> m(2, 2, 1.0);
  m.set_size(3, 4);
  TEST("size: rows", m.rows(), 3u);
  TEST("size: cols", m.cols(), 4u);
  TEST("a resized matrix is zero", m.is_zero(), true);
  m.fill(2);
  TEST("fill 2", m.array_one_norm(), 24.0);
  TEST("row pointers follow the resize", m.data_array()[2][3], 2.0);
  m.set_size(0, 0);
  TEST("resize to empty", m.empty(), true);
  double storage[3] = {1, 2, 3};
  vnl_vector_ref<double> ref(3, storage);
  TEST("a view keeps its size (set_size to its own size is fine)", ref.set_size(3) && ref.size() == 3, true);
}

TESTMAIN(test_resize)
