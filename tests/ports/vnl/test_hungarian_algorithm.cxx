// SPDX-License-Identifier: BSD-3-Clause
// vnl_hungarian_algorithm as upstream's test_hungarian_algorithm.cxx: a matrix whose optimum
// is the diagonal, a 6x6 with known optimum, rectangular matrices both ways, and random
// problems with a planted cheap assignment; the total cost is checked against brute force.
#include <algorithm>
#include <numeric>
#include <vector>

#include "testlib/testlib_test.h"
#include "vnl/vnl_hungarian_algorithm.h"
#include "vnl/vnl_random.h"

namespace {
/// The cheapest assignment of a small square matrix, by trying every permutation.
double brute_force(const vnl_matrix<double>& cost) {
  std::vector<unsigned> perm(cost.rows());
  std::iota(perm.begin(), perm.end(), 0u);
  double best = 1e300;
  do {
    double total = 0;
    for (unsigned i = 0; i < perm.size(); ++i) total += cost(i, perm[i]);
    best = std::min(best, total);
  } while (std::next_permutation(perm.begin(), perm.end()));
  return best;
}
}  // namespace

static void test_hungarian_algorithm() {
  vnl_matrix<int> cost(4, 4, 20);
  for (unsigned i = 0; i < 4; ++i) cost(i, i) = int(i) + 6;  // diagonal 6 + 7 + 8 + 9 = 30
  cost(0, 1) = 7;  // no cheaper: swapping rows 0 and 1 costs 7 + 20
  vnl_hungarian_algorithm<int> h;
  h.SetCostMatrix(cost);
  h.StartAssignment();
  TEST("assignment matrix is the identity", h.GetAssignmentMatrix().is_identity(), true);
  TEST("total cost", h.GetTotalCost(), 30);

  const vnl_matrix<double> c6{{2, 3.0, 1, 0.1, 2, 7}, {1, 0, 1, 2, 3.0, 4}, {0, 0, 9, 5, 4.4, 2},
                              {1, 5, 6, 3, 0, 1},     {0, 1, 2, 0, 1, 2},   {2, 3, 1, 0.1, 1, 1}};
  vnl_hungarian_algorithm<double> h6(c6);
  TEST_NEAR("6x6 total cost is the brute-force optimum", h6.GetTotalCost(), brute_force(c6), 1e-12);
  const std::vector<unsigned> a6 = h6.GetAssignmentVector();
  std::vector<unsigned> sorted(a6);
  std::sort(sorted.begin(), sorted.end());
  TEST("6x6 assignment is a permutation", sorted == std::vector<unsigned>({0, 1, 2, 3, 4, 5}), true);

  const vnl_matrix<double> wide{{4, 1, 3, 9}, {2, 0, 5, 1}};
  const std::vector<unsigned> aw = vnl_hungarian_algorithm<double>(wide);
  TEST("2x4: both rows assigned", aw.size() == 2 && aw[0] == 1 && aw[1] == 3, true);
  const vnl_matrix<double> tall = wide.transpose();
  vnl_hungarian_algorithm<double> ht(tall);
  const std::vector<unsigned> at = ht.GetAssignmentVector();
  TEST("4x2: two rows assigned, two left out",
       at[1] == 0 && at[3] == 1 && at[0] == unsigned(-1) && at[2] == unsigned(-1), true);
  TEST_NEAR("4x2 total cost", ht.GetTotalCost(), 2.0, 0.0);

  vnl_random rng(42);
  bool all_optimal = true;
  for (int trial = 0; trial < 20; ++trial) {
    vnl_matrix<double> r(6, 6);
    for (double& x : r) x = rng.drand32(10.0, 100.0);
    std::vector<unsigned> planted(6);
    std::iota(planted.begin(), planted.end(), 0u);
    for (unsigned i = 5; i > 0; --i) std::swap(planted[i], planted[static_cast<unsigned>(rng.next_int32(int(i)))]);
    for (unsigned i = 0; i < 6; ++i) r(i, planted[i]) = rng.drand32(0.0, 5.0);
    const std::vector<unsigned> found = vnl_hungarian_algorithm<double>(r);
    all_optimal = all_optimal && found == planted;
  }
  TEST("20 random 6x6 problems recover the planted cheap assignment", all_optimal, true);
}

TESTMAIN(test_hungarian_algorithm)
