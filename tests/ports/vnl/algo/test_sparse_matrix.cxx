// SPDX-License-Identifier: BSD-3-Clause
// Upstream's algo test_sparse_matrix.cxx: sparse products, sums and differences against dense
// ones (upstream prints them, and times large products, which we do not), and
// vnl_sparse_symmetric_eigensystem's smallest pairs, plain and with B = I, and a generalised
// problem, against the dense eigensystems.
#include <cmath>

#include "testlib/testlib_test.h"
#include "vnl/algo/vnl_generalized_eigensystem.h"
#include "vnl/algo/vnl_sparse_symmetric_eigensystem.h"
#include "vnl/algo/vnl_symmetric_eigensystem.h"
#include "vnl/vnl_sparse_matrix.h"

namespace {

vnl_matrix<double> dense(const vnl_sparse_matrix<double>& s) {
  vnl_matrix<double> d(s.rows(), s.cols(), 0.0);
  for (unsigned r = 0; r < s.rows(); ++r)
    for (unsigned c = 0; c < s.cols(); ++c) d(r, c) = s(r, c);
  return d;
}

void doTest1() {
  constexpr unsigned n = 20;
  vnl_sparse_matrix<double> m1(n, n), m2(n, n);
  for (unsigned i = 0; i < n; i++) {
    m1(i, i) = 2.0;
    m1(i, (i + 3) % n) = 1.0;
    m2(i, i) = 2.0;
    m2(i, (i + n - 3) % n) = 1.0;
  }
  TEST_NEAR("sparse product = dense product", (dense(m1 * m2) - dense(m1) * dense(m2)).fro_norm(), 0.0, 1e-12);
  TEST_NEAR("sparse sum = dense sum", (dense(m1 + m2) - (dense(m1) + dense(m2))).fro_norm(), 0.0, 1e-12);
  TEST_NEAR("sparse difference = dense difference", (dense(m1 - m2) - (dense(m1) - dense(m2))).fro_norm(), 0.0, 1e-12);
}

/// The symmetric n x n with i + 1 on the diagonal and 1 three places off it (cyclically).
void banded(unsigned n, vnl_sparse_matrix<double>& ms, vnl_matrix<double>& md) {
  ms = vnl_sparse_matrix<double>(n, n);
  md.set_size(n, n);
  md.fill(0.0);
  for (unsigned i = 0; i < n; i++) {
    ms(i, i) = md(i, i) = i + 1.0;
    ms(i, (i + 3) % n) = md(i, (i + 3) % n) = 1.0;
    ms(i, (i + n - 3) % n) = md(i, (i + n - 3) % n) = 1.0;
  }
}

void doTest3And4() {
  vnl_sparse_matrix<double> ms;
  vnl_matrix<double> md;
  banded(20, ms, md);
  const vnl_symmetric_eigensystem<double> ed(md);
  vnl_sparse_symmetric_eigensystem es;
  TEST("vnl_sparse_symmetric_eigensystem::CalculateNPairs()", es.CalculateNPairs(ms, 3, true, 20), 0);
  for (int i = 0; i < 3; i++) {
    TEST_NEAR("vnl_sparse_symmetric_eigensystem eigenvalue difference", es.get_eigenvalue(i) - ed.D(i, i), 0.0, 1e-10);
    const vnl_vector<double> v = es.get_eigenvector(i);
    TEST_NEAR("and A v = lambda v", (md * v - es.get_eigenvalue(i) * v).two_norm(), 0.0, 1e-10);
  }
  TEST("the largest pair comes first without `smallest`", es.CalculateNPairs(ms, 1, false) == 0 &&
                                                              std::fabs(es.get_eigenvalue(0) - ed.D(19, 19)) < 1e-10,
       true);
  TEST("asking for more pairs than unknowns is refused", es.CalculateNPairs(ms, 21) != 0, true);
}

void doTest5() {
  vnl_sparse_matrix<double> ms;
  vnl_matrix<double> md;
  banded(20, ms, md);
  vnl_sparse_matrix<double> bIdentity(20, 20);
  for (unsigned i = 0; i < 20; i++) bIdentity(i, i) = 1.0;
  const vnl_symmetric_eigensystem<double> ed(md);
  vnl_sparse_symmetric_eigensystem es;
  TEST("vnl_sparse_symmetric_eigensystem::CalculateNPairs(A, B) succeeded",
       es.CalculateNPairs(ms, bIdentity, 3, 0, 0, true, false), 0);
  for (int i = 0; i < 3; i++)
    TEST_NEAR("vnl_sparse_symmetric_eigensystem eigenvalue difference", es.get_eigenvalue(i) - ed.D(i, i), 0.0, 1e-10);
}

void doTest6() {
  constexpr int matOrd = 6;
  double Sdata[matOrd * matOrd] = {
      30.0000, -3.4273, 13.9254, 13.7049, -2.4446, 20.2380, -3.4273, 13.7049, -2.4446, 1.3659,  3.6702,  -0.2282,
      13.9254, -2.4446, 20.2380, 3.6702,  -0.2282, 28.6779, 13.7049, 1.3659,  3.6702,  12.5273, -1.6045, 3.9419,
      -2.4446, 3.6702,  -0.2282, -1.6045, 3.9419,  2.5821,  20.2380, -0.2282, 28.6779, 3.9419,  2.5821,  44.0636,
  };
  double Cdata[matOrd * matOrd] = {
      -1, 2, 2, 2, 2, 2, 2, 0, 0, 0, 0, 2, 2, 0, -1, 0, 0, 2, 2, 0, 0, -1, 0, 2, 2, 0, 0, 0, -1, 0, 2, 2, 2, 2, 0, -1,
  };
  const vnl_matrix<double> S(Sdata, matOrd, matOrd), C(Cdata, matOrd, matOrd);
  vnl_sparse_matrix<double> sparseS(matOrd, matOrd), sparseC(matOrd, matOrd);
  for (int i = 0; i < matOrd; i++)
    for (int j = 0; j < matOrd; j++) {
      if (S(i, j) != 0.0) sparseS(i, j) = S(i, j);
      if (C(i, j) != 0.0) sparseC(i, j) = C(i, j);
    }
  const vnl_generalized_eigensystem gev(C, S);
  vnl_sparse_symmetric_eigensystem sse;
  const int evCount = matOrd - 1;
  TEST("vnl_sparse_symmetric_eigensystem::CalculateNPairs(A,B) succeeded",
       sse.CalculateNPairs(sparseC, sparseS, evCount, 0, 0, true, false), 0);
  for (int i = 0; i < evCount; ++i)
    TEST_NEAR("vnl_sparse_symmetric_eigensystem general case eigenvalue difference",
              sse.get_eigenvalue(i) - gev.D(i, i), 0.0, 1e-10);
  for (int k = 0; k < evCount; k++) {
    const double same = (sse.get_eigenvector(k) - gev.V.get_column(k)).two_norm();
    const double opposite = (sse.get_eigenvector(k) + gev.V.get_column(k)).two_norm();
    TEST_NEAR("vnl_sparse_symmetric_eigensystem general case eigenvector difference", same < opposite ? same : opposite,
              0.0, 1e-10);
  }
}

}  // namespace

static void test_sparse_matrix() {
  doTest1();
  doTest3And4();
  doTest5();
  doTest6();
}

TESTMAIN(test_sparse_matrix)
