// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_sparse_lst_sqr_function.h: the residual function of a sparse
/// least-squares problem (bundle adjustment's shape), for a sparse Levenberg-Marquardt. The
/// unknowns are blocks a_i, blocks b_j and one shared block c; residual block e_ij exists where
/// the mask (a vnl_crs_index) says so and depends on a_i, b_j and c only, so its Jacobian is
/// the three blocks A_ij, B_ij and C_ij. Subclasses override fij and, with use_gradient,
/// jac_Aij/jac_Bij/jac_Cij; the fd_ versions give central differences. Templated on the scalar
/// as vnl_sparse_lst_sqr_function_of<T>; `vnl_sparse_lst_sqr_function` is upstream's, on
/// double in every build, as vnl_least_squares_function.
#pragma once

#ifdef vnl_sparse_lst_sqr_function_h_
#error "edgetrack's drop-in vnl/vnl_sparse_lst_sqr_function.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <vector>

#include "real/real.h"
#include "vnl/vnl_crs_index.h"
#include "vnl/vnl_matrix.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

template <class T>
class vnl_sparse_lst_sqr_function_of {
 public:
  enum UseGradient { no_gradient, use_gradient };
  enum UseWeights { no_weights, use_weights };
  /// Set by f or the Jacobians to make the minimiser stop.
  bool failure = false;

  /// num_a blocks of num_params_per_a, num_b of num_params_per_b, every (i, j) present.
  vnl_sparse_lst_sqr_function_of(unsigned int num_a, unsigned int num_params_per_a, unsigned int num_b,
                                 unsigned int num_params_per_b, unsigned int num_params_c,
                                 unsigned int num_residuals_per_e, UseGradient g = use_gradient,
                                 UseWeights w = no_weights);
  /// Only the (i, j) with xmask[i][j] have residuals.
  vnl_sparse_lst_sqr_function_of(unsigned int num_a, unsigned int num_params_per_a, unsigned int num_b,
                                 unsigned int num_params_per_b, unsigned int num_params_c,
                                 const std::vector<std::vector<bool>>& xmask, unsigned int num_residuals_per_e,
                                 UseGradient g = use_gradient, UseWeights w = no_weights);
  /// Blocks of individual sizes; e_sizes has one entry per true element of xmask, row by row.
  vnl_sparse_lst_sqr_function_of(const std::vector<unsigned int>& a_sizes, const std::vector<unsigned int>& b_sizes,
                                 unsigned int num_params_c, const std::vector<unsigned int>& e_sizes,
                                 const std::vector<std::vector<bool>>& xmask, UseGradient g = use_gradient,
                                 UseWeights w = no_weights);
  virtual ~vnl_sparse_lst_sqr_function_of() = default;

  void throw_failure() { failure = true; }
  void clear_failure() { failure = false; }

  /// All residual blocks: e's block k (of pair (i, j)) from fij.
  virtual void f(const vnl_vector<T>& a, const vnl_vector<T>& b, const vnl_vector<T>& c, vnl_vector<T>& e);
  /// All Jacobian blocks (one per residual block) from jac_Aij, jac_Bij and jac_Cij.
  virtual void jac_blocks(const vnl_vector<T>& a, const vnl_vector<T>& b, const vnl_vector<T>& c,
                          std::vector<vnl_matrix<T>>& A, std::vector<vnl_matrix<T>>& B, std::vector<vnl_matrix<T>>& C);
  /// The same by central differences of step `stepsize`.
  virtual void fd_jac_blocks(const vnl_vector<T>& a, const vnl_vector<T>& b, const vnl_vector<T>& c,
                             std::vector<vnl_matrix<T>>& A, std::vector<vnl_matrix<T>>& B,
                             std::vector<vnl_matrix<T>>& C, T stepsize);
  /// One weight per residual block, from compute_weight_ij (robust estimation).
  virtual void compute_weights(const vnl_vector<T>& a, const vnl_vector<T>& b, const vnl_vector<T>& c,
                               const vnl_vector<T>& e, vnl_vector<T>& weights);
  virtual void apply_weights(const vnl_vector<T>& weights, vnl_vector<T>& e);
  virtual void apply_weights(const vnl_vector<T>& weights, std::vector<vnl_matrix<T>>& A, std::vector<vnl_matrix<T>>& B,
                             std::vector<vnl_matrix<T>>& C);

  /// Residual block e_ij; the default only warns (a subclass must override it).
  virtual void fij(int i, int j, const vnl_vector<T>& ai, const vnl_vector<T>& bj, const vnl_vector<T>& c,
                   vnl_vector<T>& fij);
  virtual void jac_Aij(unsigned int i, unsigned int j, const vnl_vector<T>& ai, const vnl_vector<T>& bj,
                       const vnl_vector<T>& c, vnl_matrix<T>& Aij);
  virtual void jac_Bij(unsigned int i, unsigned int j, const vnl_vector<T>& ai, const vnl_vector<T>& bj,
                       const vnl_vector<T>& c, vnl_matrix<T>& Bij);
  virtual void jac_Cij(unsigned int i, unsigned int j, const vnl_vector<T>& ai, const vnl_vector<T>& bj,
                       const vnl_vector<T>& c, vnl_matrix<T>& Cij);
  void fd_jac_Aij(int i, int j, const vnl_vector<T>& ai, const vnl_vector<T>& bj, const vnl_vector<T>& c,
                  vnl_matrix<T>& Aij, T stepsize);
  void fd_jac_Bij(int i, int j, const vnl_vector<T>& ai, const vnl_vector<T>& bj, const vnl_vector<T>& c,
                  vnl_matrix<T>& Bij, T stepsize);
  void fd_jac_Cij(int i, int j, const vnl_vector<T>& ai, const vnl_vector<T>& bj, const vnl_vector<T>& c,
                  vnl_matrix<T>& Cij, T stepsize);
  /// The weight of block (i, j); 1 by default.
  virtual void compute_weight_ij(int i, int j, const vnl_vector<T>& ai, const vnl_vector<T>& bj, const vnl_vector<T>& c,
                                 const vnl_vector<T>& fij, T& weight);
  virtual void apply_weight_ij(int i, int j, const T& weight, vnl_vector<T>& fij);
  virtual void apply_weight_ij(int i, int j, const T& weight, vnl_matrix<T>& Aij, vnl_matrix<T>& Bij,
                               vnl_matrix<T>& Cij);
  /// Called by the minimiser once per iteration; does nothing by default.
  virtual void trace(int iteration, const vnl_vector<T>& a, const vnl_vector<T>& b, const vnl_vector<T>& c,
                     const vnl_vector<T>& e);

  unsigned int number_of_params_a(int i) const { return indices_a_[i + 1] - indices_a_[i]; }
  unsigned int number_of_params_b(int j) const { return indices_b_[j + 1] - indices_b_[j]; }
  unsigned int number_of_params_c() const { return num_params_c_; }
  unsigned int number_of_residuals(int k) const { return indices_e_[k + 1] - indices_e_[k]; }
  /// Residuals of pair (i, j), 0 where the mask has none.
  unsigned int number_of_residuals(int i, int j) const {
    const int k = residual_indices_(i, j);
    return k < 0 ? 0 : number_of_residuals(k);
  }
  /// Offsets of block a_i in a, b_j in b and residual block k in e.
  unsigned int index_a(int i) const { return indices_a_[i]; }
  unsigned int index_b(int j) const { return indices_b_[j]; }
  unsigned int index_e(int k) const { return indices_e_[k]; }
  unsigned int number_of_a() const { return static_cast<unsigned int>(indices_a_.size() - 1); }
  unsigned int number_of_b() const { return static_cast<unsigned int>(indices_b_.size() - 1); }
  unsigned int number_of_e() const { return static_cast<unsigned int>(indices_e_.size() - 1); }
  bool has_gradient() const { return use_gradient_; }
  bool has_weights() const { return use_weights_; }
  const vnl_crs_index& residual_indices() const { return residual_indices_; }

 protected:
  vnl_crs_index residual_indices_;
  std::vector<unsigned int> indices_a_;
  std::vector<unsigned int> indices_b_;
  unsigned int num_params_c_;
  std::vector<unsigned int> indices_e_;
  bool use_gradient_;
  bool use_weights_;

 private:
  /// Calls visit(i, j, k, ai, bj) for every residual block k of pair (i, j), row by row.
  template <class Visit>
  void for_each_block(const vnl_vector<T>& a, const vnl_vector<T>& b, Visit visit);
  /// Central differences of fij in the unknowns of `which` (0: ai, 1: bj, 2: c) into J.
  void central_differences(int which, int i, int j, const vnl_vector<T>& ai, const vnl_vector<T>& bj,
                           const vnl_vector<T>& c, vnl_matrix<T>& J, T stepsize);
  void dim_warning(unsigned int n_unknowns, unsigned int n_residuals);
};

using vnl_sparse_lst_sqr_function = vnl_sparse_lst_sqr_function_of<double>;

}  // inline namespace edgetrack_ports
