// SPDX-License-Identifier: BSD-3-Clause
// vnl_sparse_lu as upstream's algo test_sparse_lu.cxx: Sparse 1.3's mat0 (solution, determinant
// and transposed solution), its mat5 (a permutation, so pivoting is needed) and a birth-death
// queue matrix (solution and condition). Upstream's error bound is Sparse's own roundoff
// estimate; ours is checked against its definition.
#include <cmath>
#include <limits>
#include <vector>

#include "testlib/testlib_test.h"
#include "vnl/algo/vnl_sparse_lu.h"
#include "vnl/vnl_sparse_matrix.h"

static void test_sparse_lu() {
  vnl_sparse_matrix<double> A(4, 4);
  A.set_row(0, {0, 1}, {2.0, -1.0});
  A.set_row(1, {0, 1, 2}, {-1.0, 3.0, -1.0});
  A.set_row(2, {1, 2, 3}, {-1.0, 3.0, -1.0});
  A.set_row(3, {2, 3}, {-1.0, 3.0});
  vnl_vector<double> b(4, 0.0), x(4);
  b[0] = 34.0;
  vnl_sparse_lu lu(A, vnl_sparse_lu::verbose);
  lu.solve(b, &x);
  TEST_NEAR("solution of mat0 example", x[0], 21, 1.e-03);
  vnl_vector<double> check(4);
  A.mult(x, check);
  TEST_NEAR("A x = b", (check - b).two_norm(), 0.0, 1e-12);
  TEST_NEAR("determinant of mat0 example", lu.determinant(), 34, 1.e-03);
  lu.solve_transpose(b, &x);
  TEST_NEAR("transpose solution of mat0 example", x[2], 3, 1.e-03);
  A.pre_mult(x, check);
  TEST_NEAR("A^T x = b", (check - b).two_norm(), 0.0, 1e-12);

  vnl_sparse_matrix<double> Ap(3, 3);
  Ap(0, 1) = 1;
  Ap(1, 2) = 1;
  Ap(2, 0) = 1;
  vnl_vector<double> bp(3), xp(3);
  bp[0] = 2.0;
  bp[1] = 3.0;
  bp[2] = 1.0;
  vnl_sparse_lu lup(Ap, vnl_sparse_lu::verbose);
  lup.solve(bp, &xp);
  TEST_NEAR("solution of mat5 example", xp[2], 3, 1.e-03);
  TEST_NEAR("the permutation's determinant is +1", lup.determinant(), 1.0, 1e-15);

  const double s = -0.01, l = 0.5, m = 0.5;
  vnl_sparse_matrix<double> S(6, 6);
  S(0, 0) = s + l;
  S(0, 1) = -l;
  S(1, 0) = -m;
  S(1, 1) = s + l + m;
  S(1, 2) = -l;
  S(2, 1) = -m;
  S(2, 2) = s + l + m;
  S(3, 3) = s + l + m;
  S(3, 4) = -l;
  S(4, 3) = -m;
  S(4, 4) = s + l + m;
  S(4, 5) = -l;
  S(5, 4) = -m;
  S(5, 5) = m + s;
  vnl_vector<double> bbd(6, 0.0), xbd(6);
  bbd[2] = l;
  bbd[3] = m;
  vnl_sparse_lu lubd(S, vnl_sparse_lu::estimate_condition);
  lubd.solve(bbd, &xbd);
  TEST_NEAR("test solution of birth-death matrix", xbd[2], 1.06622, 1.e-04);
  TEST_NEAR("birth-death matrix condition number", lubd.rcond(), 0.03756, 1.e-04);
  TEST("the error bound is n eps max|U| / rcond, small and positive",
       lubd.max_error_bound() > 0 && lubd.max_error_bound() < 1e-12, true);
  TEST("quiet mode computes no condition", vnl_sparse_lu(S).rcond(), 0.0);
}

TESTMAIN(test_sparse_lu)
