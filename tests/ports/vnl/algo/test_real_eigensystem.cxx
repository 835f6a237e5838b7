// SPDX-License-Identifier: BSD-3-Clause
// vnl_real_eigensystem as upstream's algo test_real_eigensystem.cxx: upstream's symmetric 6 x 6
// has real eigenvalues and S Vreal = Vreal D; its "unsympathetic" 4 x 4 recomposes in complex
// arithmetic; plus a rotation block with a complex pair.
#include <cmath>
#include <algorithm>
#include <complex>
#include <string>

#include "testlib/testlib_test.h"
#include "vnl/algo/vnl_real_eigensystem.h"
#include "vnl/vnl_complexify.h"
#include "vnl/vnl_trace.h"

namespace {
using C = std::complex<double>;

/// The eigenvalues sum to the trace and every eigenvector has unit length (so a result of
/// zeros cannot pass the recomposition tests).
void check_nontrivial(const vnl_matrix<double>& M, const vnl_real_eigensystem& eig, const std::string& name) {
  C sum = 0;
  double worst_length = 0;
  for (unsigned i = 0; i < M.rows(); ++i) {
    sum += eig.D(i, i);
    worst_length = std::max(worst_length, std::fabs(eig.V.get_column(i).two_norm() - 1));
  }
  TEST_NEAR("the eigenvalues sum to the trace (" + name + ")", std::abs(sum - C(vnl_trace(M))), 0.0, 1e-9);
  TEST_NEAR("unit eigenvectors (" + name + ")", worst_length, 0.0, 1e-12);
}

void test_6x6() {
  double Sdata[36] = {
      30.0000, -3.4273, 13.9254, 13.7049, -2.4446, 20.2380, -3.4273, 13.7049, -2.4446, 1.3659,  3.6702,  -0.2282,
      13.9254, -2.4446, 20.2380, 3.6702,  -0.2282, 28.6779, 13.7049, 1.3659,  3.6702,  12.5273, -1.6045, 3.9419,
      -2.4446, 3.6702,  -0.2282, -1.6045, 3.9419,  2.5821,  20.2380, -0.2282, 28.6779, 3.9419,  2.5821,  44.0636,
  };
  const vnl_matrix<double> S(Sdata, 6, 6);
  const vnl_real_eigensystem eig(S);
  vnl_diag_matrix<C> D(eig.D.rows());
  bool all_real = true;
  for (unsigned i = 0; i < eig.D.rows(); ++i) {
    all_real = all_real && std::imag(eig.D(i, i)) < 1e-15;
    D(i, i) = std::real(eig.D(i, i));
  }
  TEST("All real", all_real, true);
  const vnl_matrix<C> diff = vnl_complexify(S * eig.Vreal) - vnl_complexify(eig.Vreal) * D;
  TEST_NEAR("recompose residual", diff.fro_norm(), 0.0, 1e-12);
  check_nontrivial(S, eig, "6 x 6");
}

void test_4x4() {
  double Xdata[] = {686, 526, 701, 47, 588, 91, 910, 736, 930, 653, 762, 328, 846, 415, 262, 632};
  const vnl_matrix<double> X(Xdata, 4, 4);
  const vnl_real_eigensystem eig(X);
  const vnl_matrix<C> diff = vnl_complexify(X) * eig.V - eig.V * eig.D;
  TEST_NEAR("recompose residual", diff.fro_norm(), 0.0, 1e-11);
  check_nontrivial(X, eig, "4 x 4");
}

void test_complex_pair() {
  // A rotation by 0.5 rad scaled by 2, beside the eigenvalue 3: 2 e^{+-0.5 i} and 3.
  vnl_matrix<double> R(3, 3, 0.0);
  R(0, 0) = R(1, 1) = 2 * std::cos(0.5);
  R(0, 1) = -2 * std::sin(0.5);
  R(1, 0) = 2 * std::sin(0.5);
  R(2, 2) = 3;
  const vnl_real_eigensystem eig(R);
  int pairs = 0;
  for (unsigned i = 0; i < 3; ++i) pairs += std::abs(eig.D(i, i) - std::polar(2.0, 0.5)) < 1e-12;
  TEST("the pair 2 exp(+0.5 i) is found", pairs, 1);
  const vnl_matrix<C> diff = vnl_complexify(R) * eig.V - eig.V * eig.D;
  TEST_NEAR("the complex eigenvectors recompose", diff.fro_norm(), 0.0, 1e-12);
  check_nontrivial(R, eig, "rotation");
}
}  // namespace

static void test_real_eigensystem() {
  test_6x6();
  test_4x4();
  test_complex_pair();
}

TESTMAIN(test_real_eigensystem)
