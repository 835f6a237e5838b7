// SPDX-License-Identifier: BSD-3-Clause
/// Definitions for vnl_sparse_lst_sqr_function.h. Include it only to instantiate the class for
/// a scalar that the library does not instantiate.
#pragma once

#include <cassert>
#include <iostream>

#include "vnl/vnl_sparse_lst_sqr_function.h"
#include "vnl/vnl_vector_ref.h"

inline namespace edgetrack_ports {

namespace vnl_sparse_lst_sqr_detail {
/// Offsets 0, size, 2 size, ... (count + 1 of them).
inline std::vector<unsigned int> uniform_offsets(std::size_t count, unsigned int size) {
  std::vector<unsigned int> offsets(count + 1, 0);
  for (std::size_t i = 1; i < offsets.size(); ++i) offsets[i] = offsets[i - 1] + size;
  return offsets;
}
/// Offsets of consecutive blocks of the given sizes.
inline std::vector<unsigned int> running_offsets(const std::vector<unsigned int>& sizes) {
  std::vector<unsigned int> offsets(sizes.size() + 1, 0);
  for (std::size_t i = 0; i < sizes.size(); ++i) offsets[i + 1] = offsets[i] + sizes[i];
  return offsets;
}
inline std::vector<std::vector<bool>> full_mask(unsigned int rows, unsigned int cols) {
  return std::vector<std::vector<bool>>(rows, std::vector<bool>(cols, true));
}
}  // namespace vnl_sparse_lst_sqr_detail

template <class T>
vnl_sparse_lst_sqr_function_of<T>::vnl_sparse_lst_sqr_function_of(unsigned int num_a, unsigned int num_params_per_a,
                                                                  unsigned int num_b, unsigned int num_params_per_b,
                                                                  unsigned int num_params_c,
                                                                  unsigned int num_residuals_per_e, UseGradient g,
                                                                  UseWeights w)
    : vnl_sparse_lst_sqr_function_of(num_a, num_params_per_a, num_b, num_params_per_b, num_params_c,
                                     vnl_sparse_lst_sqr_detail::full_mask(num_a, num_b), num_residuals_per_e, g, w) {}

template <class T>
vnl_sparse_lst_sqr_function_of<T>::vnl_sparse_lst_sqr_function_of(unsigned int num_a, unsigned int num_params_per_a,
                                                                  unsigned int num_b, unsigned int num_params_per_b,
                                                                  unsigned int num_params_c,
                                                                  const std::vector<std::vector<bool>>& xmask,
                                                                  unsigned int num_residuals_per_e, UseGradient g,
                                                                  UseWeights w)
    : residual_indices_(xmask),
      indices_a_(vnl_sparse_lst_sqr_detail::uniform_offsets(num_a, num_params_per_a)),
      indices_b_(vnl_sparse_lst_sqr_detail::uniform_offsets(num_b, num_params_per_b)),
      num_params_c_(num_params_c),
      indices_e_(vnl_sparse_lst_sqr_detail::uniform_offsets(residual_indices_.num_non_zero(), num_residuals_per_e)),
      use_gradient_(g == use_gradient),
      use_weights_(w == use_weights) {
  dim_warning(indices_a_.back() + indices_b_.back() + num_params_c, indices_e_.back());
}

template <class T>
vnl_sparse_lst_sqr_function_of<T>::vnl_sparse_lst_sqr_function_of(
    const std::vector<unsigned int>& a_sizes, const std::vector<unsigned int>& b_sizes, unsigned int num_params_c,
    const std::vector<unsigned int>& e_sizes, const std::vector<std::vector<bool>>& xmask, UseGradient g, UseWeights w)
    : residual_indices_(xmask),
      indices_a_(vnl_sparse_lst_sqr_detail::running_offsets(a_sizes)),
      indices_b_(vnl_sparse_lst_sqr_detail::running_offsets(b_sizes)),
      num_params_c_(num_params_c),
      indices_e_(vnl_sparse_lst_sqr_detail::running_offsets(e_sizes)),
      use_gradient_(g == use_gradient),
      use_weights_(w == use_weights) {
  assert(residual_indices_.num_non_zero() == static_cast<int>(e_sizes.size()));
  assert(residual_indices_.num_rows() == static_cast<int>(a_sizes.size()));
  assert(residual_indices_.num_cols() == static_cast<int>(b_sizes.size()));
  dim_warning(indices_a_.back() + indices_b_.back() + num_params_c, indices_e_.back());
}

template <class T>
void vnl_sparse_lst_sqr_function_of<T>::dim_warning(unsigned int n_unknowns, unsigned int n_residuals) {
  if (n_unknowns > n_residuals) {
    std::cerr << "vnl_sparse_lst_sqr_function: WARNING: unknowns(" << n_unknowns << ") > residuals(" << n_residuals
              << ")\n";
  }
}

template <class T>
template <class Visit>
void vnl_sparse_lst_sqr_function_of<T>::for_each_block(const vnl_vector<T>& a, const vnl_vector<T>& b, Visit visit) {
  for (unsigned int i = 0; i < number_of_a(); ++i) {
    const vnl_vector_ref<T> ai(number_of_params_a(i), const_cast<T*>(a.data_block()) + index_a(i));
    for (const auto& [k, j] : residual_indices_.sparse_row(static_cast<int>(i))) {
      const vnl_vector_ref<T> bj(number_of_params_b(j), const_cast<T*>(b.data_block()) + index_b(j));
      visit(static_cast<int>(i), j, k, ai, bj);
    }
  }
}

template <class T>
void vnl_sparse_lst_sqr_function_of<T>::f(const vnl_vector<T>& a, const vnl_vector<T>& b, const vnl_vector<T>& c,
                                          vnl_vector<T>& e) {
  for_each_block(a, b, [&](int i, int j, int k, const vnl_vector<T>& ai, const vnl_vector<T>& bj) {
    vnl_vector_ref<T> eij(number_of_residuals(k), e.data_block() + index_e(k));
    fij(i, j, ai, bj, c, eij);
  });
}

template <class T>
void vnl_sparse_lst_sqr_function_of<T>::jac_blocks(const vnl_vector<T>& a, const vnl_vector<T>& b,
                                                   const vnl_vector<T>& c, std::vector<vnl_matrix<T>>& A,
                                                   std::vector<vnl_matrix<T>>& B, std::vector<vnl_matrix<T>>& C) {
  for_each_block(a, b, [&](int i, int j, int k, const vnl_vector<T>& ai, const vnl_vector<T>& bj) {
    const auto ui = static_cast<unsigned int>(i), uj = static_cast<unsigned int>(j);
    jac_Aij(ui, uj, ai, bj, c, A[k]);
    jac_Bij(ui, uj, ai, bj, c, B[k]);
    jac_Cij(ui, uj, ai, bj, c, C[k]);
  });
}

template <class T>
void vnl_sparse_lst_sqr_function_of<T>::fd_jac_blocks(const vnl_vector<T>& a, const vnl_vector<T>& b,
                                                      const vnl_vector<T>& c, std::vector<vnl_matrix<T>>& A,
                                                      std::vector<vnl_matrix<T>>& B, std::vector<vnl_matrix<T>>& C,
                                                      T stepsize) {
  for_each_block(a, b, [&](int i, int j, int k, const vnl_vector<T>& ai, const vnl_vector<T>& bj) {
    fd_jac_Aij(i, j, ai, bj, c, A[k], stepsize);
    fd_jac_Bij(i, j, ai, bj, c, B[k], stepsize);
    fd_jac_Cij(i, j, ai, bj, c, C[k], stepsize);
  });
}

template <class T>
void vnl_sparse_lst_sqr_function_of<T>::compute_weights(const vnl_vector<T>& a, const vnl_vector<T>& b,
                                                        const vnl_vector<T>& c, const vnl_vector<T>& e,
                                                        vnl_vector<T>& weights) {
  for_each_block(a, b, [&](int i, int j, int k, const vnl_vector<T>& ai, const vnl_vector<T>& bj) {
    const vnl_vector_ref<T> eij(number_of_residuals(k), const_cast<T*>(e.data_block()) + index_e(k));
    compute_weight_ij(i, j, ai, bj, c, eij, weights[k]);
  });
}

template <class T>
void vnl_sparse_lst_sqr_function_of<T>::apply_weights(const vnl_vector<T>& weights, vnl_vector<T>& e) {
  for (unsigned int i = 0; i < number_of_a(); ++i) {
    for (const auto& [k, j] : residual_indices_.sparse_row(static_cast<int>(i))) {
      vnl_vector_ref<T> eij(number_of_residuals(k), e.data_block() + index_e(k));
      apply_weight_ij(static_cast<int>(i), j, weights[k], eij);
    }
  }
}

template <class T>
void vnl_sparse_lst_sqr_function_of<T>::apply_weights(const vnl_vector<T>& weights, std::vector<vnl_matrix<T>>& A,
                                                      std::vector<vnl_matrix<T>>& B, std::vector<vnl_matrix<T>>& C) {
  for (unsigned int i = 0; i < number_of_a(); ++i) {
    for (const auto& [k, j] : residual_indices_.sparse_row(static_cast<int>(i))) {
      apply_weight_ij(static_cast<int>(i), j, weights[k], A[k], B[k], C[k]);
    }
  }
}

template <class T>
void vnl_sparse_lst_sqr_function_of<T>::fij(int, int, const vnl_vector<T>&, const vnl_vector<T>&, const vnl_vector<T>&,
                                            vnl_vector<T>&) {
  std::cerr << "Warning: fij() called but not implemented in derived class\n";
}

template <class T>
void vnl_sparse_lst_sqr_function_of<T>::jac_Aij(unsigned int, unsigned int, const vnl_vector<T>&, const vnl_vector<T>&,
                                                const vnl_vector<T>&, vnl_matrix<T>&) {
  std::cerr << "Warning: jac_Aij() called but not implemented in derived class\n";
}

template <class T>
void vnl_sparse_lst_sqr_function_of<T>::jac_Bij(unsigned int, unsigned int, const vnl_vector<T>&, const vnl_vector<T>&,
                                                const vnl_vector<T>&, vnl_matrix<T>&) {
  std::cerr << "Warning: jac_Bij() called but not implemented in derived class\n";
}

template <class T>
void vnl_sparse_lst_sqr_function_of<T>::jac_Cij(unsigned int, unsigned int, const vnl_vector<T>&, const vnl_vector<T>&,
                                                const vnl_vector<T>&, vnl_matrix<T>&) {
  if (num_params_c_ > 0) std::cerr << "Warning: jac_Cij() called but not implemented in derived class\n";
}

template <class T>
void vnl_sparse_lst_sqr_function_of<T>::central_differences(int which, int i, int j, const vnl_vector<T>& ai,
                                                            const vnl_vector<T>& bj, const vnl_vector<T>& c,
                                                            vnl_matrix<T>& J, T stepsize) {
  const vnl_vector<T>& base = which == 0 ? ai : which == 1 ? bj : c;
  vnl_vector<T> moved = base;
  const vnl_vector<T>& a_arg = which == 0 ? moved : ai;
  const vnl_vector<T>& b_arg = which == 1 ? moved : bj;
  const vnl_vector<T>& c_arg = which == 2 ? moved : c;
  assert(J.columns() == base.size() && J.rows() == number_of_residuals(i, j));
  vnl_vector<T> fplus(J.rows()), fminus(J.rows());
  for (unsigned int u = 0; u < base.size(); ++u) {
    const T plus = moved[u] = base[u] + stepsize;
    fij(i, j, a_arg, b_arg, c_arg, fplus);
    const T minus = moved[u] = base[u] - stepsize;
    fij(i, j, a_arg, b_arg, c_arg, fminus);
    moved[u] = base[u];
    const T span = plus - minus;  // the step actually taken, after rounding
    for (unsigned int r = 0; r < J.rows(); ++r) J(r, u) = (fplus[r] - fminus[r]) / span;
  }
}

template <class T>
void vnl_sparse_lst_sqr_function_of<T>::fd_jac_Aij(int i, int j, const vnl_vector<T>& ai, const vnl_vector<T>& bj,
                                                   const vnl_vector<T>& c, vnl_matrix<T>& Aij, T stepsize) {
  assert(ai.size() == number_of_params_a(i));
  central_differences(0, i, j, ai, bj, c, Aij, stepsize);
}

template <class T>
void vnl_sparse_lst_sqr_function_of<T>::fd_jac_Bij(int i, int j, const vnl_vector<T>& ai, const vnl_vector<T>& bj,
                                                   const vnl_vector<T>& c, vnl_matrix<T>& Bij, T stepsize) {
  assert(bj.size() == number_of_params_b(j));
  central_differences(1, i, j, ai, bj, c, Bij, stepsize);
}

template <class T>
void vnl_sparse_lst_sqr_function_of<T>::fd_jac_Cij(int i, int j, const vnl_vector<T>& ai, const vnl_vector<T>& bj,
                                                   const vnl_vector<T>& c, vnl_matrix<T>& Cij, T stepsize) {
  assert(c.size() == number_of_params_c());
  if (c.size() == 0) return;
  central_differences(2, i, j, ai, bj, c, Cij, stepsize);
}

template <class T>
void vnl_sparse_lst_sqr_function_of<T>::compute_weight_ij(int, int, const vnl_vector<T>&, const vnl_vector<T>&,
                                                          const vnl_vector<T>&, const vnl_vector<T>&, T& weight) {
  weight = T(1);
}

template <class T>
void vnl_sparse_lst_sqr_function_of<T>::apply_weight_ij(int, int, const T& weight, vnl_vector<T>& fij) {
  fij *= weight;
}

template <class T>
void vnl_sparse_lst_sqr_function_of<T>::apply_weight_ij(int, int, const T& weight, vnl_matrix<T>& Aij,
                                                        vnl_matrix<T>& Bij, vnl_matrix<T>& Cij) {
  Aij *= weight;
  Bij *= weight;
  Cij *= weight;
}

template <class T>
void vnl_sparse_lst_sqr_function_of<T>::trace(int, const vnl_vector<T>&, const vnl_vector<T>&, const vnl_vector<T>&,
                                              const vnl_vector<T>&) {}

#define VNL_SPARSE_LST_SQR_FUNCTION_INSTANTIATE(T) template class vnl_sparse_lst_sqr_function_of<T>

}  // inline namespace edgetrack_ports
