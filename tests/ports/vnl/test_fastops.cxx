// SPDX-License-Identifier: BSD-3-Clause
// vnl_fastops as upstream's test_fastops.cxx: each product and each increment/decrement equals
// the same expression written with vnl_matrix operators; plus vnl_sparse_matrix_linear_system.
#include "testlib/testlib_test.h"
#include "vnl/vnl_fastops.h"
#include "vnl/vnl_random.h"
#include "vnl/vnl_sparse_matrix_linear_system.h"

namespace {
vnl_matrix<double> random(unsigned r, unsigned c, vnl_random& rng) {
  vnl_matrix<double> m(r, c);
  for (double& x : m) x = rng.drand64(-1, 1);
  return m;
}
double distance(const vnl_matrix<double>& a, const vnl_matrix<double>& b) { return (a - b).frobenius_norm(); }
}  // namespace

static void test_fastops() {
  vnl_random rng(5);
  const vnl_matrix<double> a = random(4, 3, rng), b = random(4, 2, rng), c = random(3, 2, rng), d = random(2, 3, rng);
  const vnl_matrix<double> s = random(3, 3, rng);
  vnl_vector<double> v(4), w(3);
  for (double& x : v) x = rng.drand64(-1, 1);
  for (double& x : w) x = rng.drand64(-1, 1);
  vnl_matrix<double> out;
  vnl_fastops::AtA(out, a);
  TEST_NEAR("AtA", distance(out, a.transpose() * a), 0.0, 1e-14);
  vnl_fastops::AB(out, a, c);
  TEST_NEAR("AB", distance(out, a * c), 0.0, 1e-14);
  vnl_fastops::AtB(out, a, b);
  TEST_NEAR("AtB", distance(out, a.transpose() * b), 0.0, 1e-14);
  vnl_fastops::ABt(out, a, d);
  TEST_NEAR("ABt", distance(out, a * d.transpose()), 0.0, 1e-14);
  vnl_fastops::ABAt(out, a, s);
  TEST_NEAR("ABAt", distance(out, a * s * a.transpose()), 0.0, 1e-14);
  vnl_vector<double> out_v;
  vnl_fastops::AtB(out_v, a, v);
  TEST_NEAR("AtB (vector)", (out_v - a.transpose() * v).inf_norm(), 0.0, 1e-14);
  vnl_fastops::Ab(out_v, a, w);
  TEST_NEAR("Ab", (out_v - a * w).inf_norm(), 0.0, 1e-14);
  TEST_NEAR("btAb", vnl_fastops::btAb(s, w), dot_product(w, s * w), 1e-14);
  vnl_matrix<double> x(3, 3, 1.0);
  vnl_fastops::inc_X_by_AtA(x, a);
  TEST_NEAR("inc_X_by_AtA", distance(x, a.transpose() * a + 1.0), 0.0, 1e-14);
  vnl_fastops::dec_X_by_AtA(x, a);
  TEST_NEAR("dec_X_by_AtA", distance(x, vnl_matrix<double>(3, 3, 1.0)), 0.0, 1e-14);
  vnl_matrix<double> y(4, 2, 0.0);
  vnl_fastops::inc_X_by_AB(y, a, c);
  vnl_fastops::dec_X_by_AB(y, a, c);
  TEST_NEAR("inc then dec_X_by_AB", y.frobenius_norm(), 0.0, 1e-14);
  vnl_vector<double> z(3, 0.0);
  vnl_fastops::inc_X_by_AtB(z, a, v);
  TEST_NEAR("inc_X_by_AtB (vector)", (z - a.transpose() * v).inf_norm(), 0.0, 1e-14);
  const double p[] = {1, 2, 3}, q[] = {4, -5, 6};
  TEST("dot", vnl_fastops::dot(p, q, 3), 12.0);

  vnl_sparse_matrix<double> sm(3, 2);
  sm(0, 0) = 2, sm(1, 1) = 3, sm(2, 0) = 1;
  const vnl_vector<double> rhs{2, 3, 1};
  const vnl_sparse_matrix_linear_system<double> system(sm, rhs);
  TEST("unknowns and residuals", system.get_number_of_unknowns() == 2 && system.get_number_of_residuals() == 3, true);
  TEST_NEAR("x = (1, 1) solves it exactly", system.get_rms_error(vnl_vector<double>{1, 1}), 0.0, 1e-15);
  vnl_vector<double> at;
  system.transpose_multiply(rhs, at);
  TEST("A^T b", at[0] == 5 && at[1] == 9, true);
  vnl_vector<double> pre;
  system.apply_preconditioner(vnl_vector<double>{5, 9}, pre);
  TEST_NEAR("Jacobi preconditioner divides by diag(A^T A) = (5, 9)", pre[0] + pre[1], 2.0, 1e-15);
}

TESTMAIN(test_fastops)
