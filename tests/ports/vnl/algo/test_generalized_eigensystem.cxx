// SPDX-License-Identifier: BSD-3-Clause
// vnl_generalized_eigensystem as upstream's algo test_generalized_eigensystem.cxx: C x = lambda
// S x for upstream's 6 x 6 positive-definite S and its sparse symmetric C recomposes to 1e-12;
// plus the increasing order and the B-orthonormal eigenvectors.
#include "testlib/testlib_test.h"
#include "vnl/algo/vnl_generalized_eigensystem.h"

static void test_generalized_eigensystem() {
  double Sdata[36] = {
      30.0000, -3.4273, 13.9254, 13.7049, -2.4446, 20.2380, -3.4273, 13.7049, -2.4446, 1.3659,  3.6702,  -0.2282,
      13.9254, -2.4446, 20.2380, 3.6702,  -0.2282, 28.6779, 13.7049, 1.3659,  3.6702,  12.5273, -1.6045, 3.9419,
      -2.4446, 3.6702,  -0.2282, -1.6045, 3.9419,  2.5821,  20.2380, -0.2282, 28.6779, 3.9419,  2.5821,  44.0636,
  };
  double Cdata[36] = {
      0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 0, 0, 0, -1, 0, 0, 0, 0, 2, 0, 0,
  };
  const vnl_matrix<double> S(Sdata, 6, 6);
  const vnl_matrix<double> C(Cdata, 6, 6);
  const vnl_generalized_eigensystem gev(C, S);
  const double err = (C * gev.V - S * gev.V * gev.D).fro_norm();
  TEST_NEAR("Recomposition residual < 1e-12", err, 0.0, 1e-12);
  bool increasing = true;
  for (unsigned i = 1; i < 6; ++i) increasing = increasing && gev.D(i - 1, i - 1) <= gev.D(i, i);
  TEST("the eigenvalues increase", increasing, true);
  vnl_matrix<double> I(6, 6);
  I.set_identity();
  TEST_NEAR("V^T S V = I", (gev.V.transpose() * S * gev.V - I).fro_norm(), 0.0, 1e-10);
  TEST("n is the order", gev.n, 6);
}

TESTMAIN(test_generalized_eigensystem)
