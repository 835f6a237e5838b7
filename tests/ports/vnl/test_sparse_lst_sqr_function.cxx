// SPDX-License-Identifier: BSD-3-Clause
// vnl_sparse_lst_sqr_function as upstream's test_sparse_lst_sqr_function.cxx: a 3 x 4 problem
// with 9 of 12 residual blocks has the right block counts and offsets, its analytic Jacobian
// blocks match central differences, and computed weights scale residuals and Jacobians.
// Run for double (upstream's scalar) and the configured real; a fixed-point real takes a
// larger difference step, so that rounding (one ulp over 2 steps) stays below the tolerance.
#include <string>
#include <type_traits>
#include <vector>

#include "real/real.h"
#include "testlib/testlib_test.h"
#include "vnl/vnl_sparse_lst_sqr_function.h"

namespace {
template <class T>
class test_func1 : public vnl_sparse_lst_sqr_function_of<T> {
  using base = vnl_sparse_lst_sqr_function_of<T>;

 public:
  test_func1(unsigned int num_a, unsigned int num_b, const std::vector<std::vector<bool>>& xmask)
      : base(num_a, 2, num_b, 3, 2, xmask, 2, base::use_gradient, base::use_weights) {}

  void fij(int, int, const vnl_vector<T>& ai, const vnl_vector<T>& bj, const vnl_vector<T>& c,
           vnl_vector<T>& eij) override {
    const T b2_cubed = bj[2] * bj[2] * bj[2];
    eij[0] = (ai[0] * ai[0] - bj[0] * ai[1]) * b2_cubed + c[0] * ai[0];
    eij[1] = (ai[1] * ai[1] - bj[1] * ai[0]) * b2_cubed + c[1] * ai[1];
  }
  void jac_Aij(unsigned int, unsigned int, const vnl_vector<T>& ai, const vnl_vector<T>& bj, const vnl_vector<T>& c,
               vnl_matrix<T>& Aij) override {
    const T b2_cubed = bj[2] * bj[2] * bj[2];
    Aij(0, 0) = T(2) * ai[0] * b2_cubed + c[0];
    Aij(0, 1) = -bj[0] * b2_cubed;
    Aij(1, 0) = -bj[1] * b2_cubed;
    Aij(1, 1) = T(2) * ai[1] * b2_cubed + c[1];
  }
  void jac_Bij(unsigned int, unsigned int, const vnl_vector<T>& ai, const vnl_vector<T>& bj, const vnl_vector<T>&,
               vnl_matrix<T>& Bij) override {
    const T b2_cubed = bj[2] * bj[2] * bj[2], b2_squared = bj[2] * bj[2];
    Bij(0, 0) = -ai[1] * b2_cubed;
    Bij(0, 1) = T(0);
    Bij(0, 2) = (ai[0] * ai[0] - bj[0] * ai[1]) * T(3) * b2_squared;
    Bij(1, 0) = T(0);
    Bij(1, 1) = -ai[0] * b2_cubed;
    Bij(1, 2) = (ai[1] * ai[1] - bj[1] * ai[0]) * T(3) * b2_squared;
  }
  void jac_Cij(unsigned int, unsigned int, const vnl_vector<T>& ai, const vnl_vector<T>&, const vnl_vector<T>&,
               vnl_matrix<T>& Cij) override {
    Cij(0, 0) = ai[0];
    Cij(0, 1) = T(0);
    Cij(1, 0) = T(0);
    Cij(1, 1) = ai[1];
  }
  void compute_weight_ij(int i, int j, const vnl_vector<T>&, const vnl_vector<T>&, const vnl_vector<T>&,
                         const vnl_vector<T>&, T& weight) override {
    weight = T((i + 1) * (j + 1)) / T(static_cast<int>(this->number_of_a() * this->number_of_b()));
  }
};

template <class T>
void check_layout(const std::string& p, const test_func1<T>& f) {
  TEST((p + "number_of_a").c_str(), f.number_of_a(), 3u);
  TEST((p + "number_of_b").c_str(), f.number_of_b(), 4u);
  TEST((p + "number_of_e").c_str(), f.number_of_e(), 9u);
  bool a_ok = true, b_ok = true, e_ok = true;
  for (unsigned i = 0; i < f.number_of_a(); ++i) a_ok = a_ok && f.number_of_params_a(i) == 2 && f.index_a(i) == 2 * i;
  for (unsigned j = 0; j < f.number_of_b(); ++j) b_ok = b_ok && f.number_of_params_b(j) == 3 && f.index_b(j) == 3 * j;
  for (unsigned k = 0; k < f.number_of_e(); ++k) e_ok = e_ok && f.number_of_residuals(k) == 2 && f.index_e(k) == 2 * k;
  TEST((p + "number_of_params_a and index_a").c_str(), a_ok, true);
  TEST((p + "number_of_params_b and index_b").c_str(), b_ok, true);
  TEST((p + "number_of_params_c").c_str(), f.number_of_params_c(), 2u);
  TEST((p + "number_of_residuals and index_e").c_str(), e_ok, true);
  TEST((p + "no residuals where the mask is false").c_str(), f.number_of_residuals(0, 2), 0u);
  TEST((p + "has weights and gradient").c_str(), f.has_weights() && f.has_gradient(), true);
}

template <class T>
void check_jacobians(const std::string& p, test_func1<T>& f, T step, double tol) {
  const vnl_vector<T> ai{T(5), T(-1)}, bj{T(6) / T(5), T(3) / T(2), T(11) / T(5)}, c{T(1), T(2)};
  vnl_matrix<T> A(2, 2), B(2, 3), C(2, 2), fd_A(2, 2), fd_B(2, 3), fd_C(2, 2);
  f.jac_Aij(0, 0, ai, bj, c, A);
  f.fd_jac_Aij(0, 0, ai, bj, c, fd_A, step);
  f.jac_Bij(0, 0, ai, bj, c, B);
  f.fd_jac_Bij(0, 0, ai, bj, c, fd_B, step);
  f.jac_Cij(0, 0, ai, bj, c, C);
  f.fd_jac_Cij(0, 0, ai, bj, c, fd_C, step);
  TEST_NEAR((p + "finite difference Aij").c_str(), (A - fd_A).absolute_value_max(), 0, tol);
  TEST_NEAR((p + "finite difference Bij").c_str(), (B - fd_B).absolute_value_max(), 0, tol);
  TEST_NEAR((p + "finite difference Cij").c_str(), (C - fd_C).absolute_value_max(), 0, tol);
}

template <class T>
void check_weights(const std::string& p, test_func1<T>& f) {
  vnl_vector<T> a(f.index_a(f.number_of_a()), T(1)), b(f.index_b(f.number_of_b()), T(2)), c{T(1), T(2)};
  a[0] = T(5), a[2] = T(-1), a[5] = T(0);
  b[1] = T(1), b[5] = T(0), b[6] = T(-2);
  vnl_vector<T> e(f.index_e(f.number_of_e()));
  std::vector<vnl_matrix<T>> A(f.number_of_e(), vnl_matrix<T>(2, 2, T(0)));
  std::vector<vnl_matrix<T>> B(f.number_of_e(), vnl_matrix<T>(2, 3, T(0)));
  std::vector<vnl_matrix<T>> C(f.number_of_e(), vnl_matrix<T>(2, 2, T(0)));
  f.f(a, b, c, e);
  f.jac_blocks(a, b, c, A, B, C);
  vnl_vector<T> weights(f.number_of_e(), T(1));
  f.compute_weights(a, b, c, e, weights);
  vnl_vector<T> we = e;
  auto wA = A, wB = B, wC = C;
  f.apply_weights(weights, we);
  f.apply_weights(weights, wA, wB, wC);
  int bad_weights = 0, bad_blocks = 0, bad_residuals = 0;
  for (unsigned i = 0; i < f.number_of_a(); ++i) {
    for (unsigned j = 0; j < f.number_of_b(); ++j) {
      const int k = f.residual_indices()(i, j);
      if (k < 0) continue;
      const T w = weights[k];
      bad_weights += w != T(static_cast<int>((i + 1) * (j + 1))) / T(12);
      bad_blocks += !(wA[k] == A[k] * w && wB[k] == B[k] * w && wC[k] == C[k] * w);
      bad_residuals += !(we[2 * k] == e[2 * k] * w && we[2 * k + 1] == e[2 * k + 1] * w);
    }
  }
  TEST((p + "weight of block (i, j) is (i+1)(j+1)/12").c_str(), bad_weights, 0);
  TEST((p + "weighted Jacobian blocks").c_str(), bad_blocks, 0);
  TEST((p + "weighted residuals").c_str(), bad_residuals, 0);
  vnl_vector<T> e_again(e.size());
  test_func1<T>* as_function = &f;
  as_function->vnl_sparse_lst_sqr_function_of<T>::f(a, b, c, e_again);
  TEST((p + "f fills every residual block from fij").c_str(), e_again == e, true);
}

template <class T>
void check_function(const std::string& name, T step, double tol) {
  std::vector<std::vector<bool>> mask(3, std::vector<bool>(4, false));
  mask[0][0] = mask[0][1] = true;
  mask[1][0] = mask[1][1] = mask[1][2] = mask[1][3] = true;
  mask[2][1] = mask[2][2] = mask[2][3] = true;
  test_func1<T> f(3, 4, mask);
  const std::string p = name + ": ";
  check_layout(p, f);
  check_jacobians(p, f, step, tol);
  check_weights(p, f);
}
}  // namespace

static void test_sparse_lst_sqr_function() {
  check_function<double>("double", 0.001, 0.001);  // upstream's step and tolerance
  if constexpr (!std::is_same_v<real, double>) {
    // Central differences are exact for these functions of each unknown but bj[2], whose cube
    // gives an error of step^2 times its coefficient (26.2 / 32^2 = 0.026 here).
    check_function<real>(real_name(), real(1) / real(32), 0.05);
  }
}

TESTMAIN(test_sparse_lst_sqr_function)
