// SPDX-License-Identifier: BSD-3-Clause
// vnl_scalar_join_iterator (upstream has no test of its own): the pairs visited are exactly
// the pairs of rows with equal join values, each once, repeated keys included (the full join
// that upstream's header describes), for double and the configured real.
#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "testlib/testlib_test.h"
#include "vnl/vnl_scalar_join_iterator.h"
#include "vnl_test_types.h"

namespace {
template <class T>
struct check_join {
  static void run(const std::string& name) {
    // Join relation1's column 1 with relation2's column 0; key 3 repeats on both sides.
    const vnl_matrix<T> relation1{{T(1), T(3)}, {T(2), T(3)}, {T(7), T(9)}, {T(4), T(5)}};
    const vnl_matrix<T> relation2{{T(3), T(5)}, {T(3), T(6)}, {T(5), T(1)}, {T(8), T(0)}};
    std::vector<std::pair<unsigned, unsigned>> visited, expected;
    for (vnl_scalar_join_iterator<T> it(relation1, 1, relation2, 0); it; ++it)
      visited.emplace_back(it.row1(), it.row2());
    for (unsigned i = 0; i < relation1.rows(); ++i) {
      for (unsigned j = 0; j < relation2.rows(); ++j) {
        if (relation1(i, 1) == relation2(j, 0)) expected.emplace_back(i, j);
      }
    }
    TEST((name + ": five matching pairs").c_str(), visited.size(), std::size_t{5});
    std::sort(visited.begin(), visited.end());
    TEST((name + ": exactly the pairs with equal keys").c_str(), visited == expected, true);

    const vnl_matrix<T> none{{T(100)}, {T(200)}};
    vnl_scalar_join_iterator<T> empty(relation1, 0, none, 0);
    TEST((name + ": no common key, no pair").c_str(), empty.done() && !empty, true);
  }
};
}  // namespace

static void test_scalar_join_iterator() {
  check_join<double>::run("double");
  if (std::string(real_name()) != "double") check_join<real>::run(real_name());
}

TESTMAIN(test_scalar_join_iterator)
