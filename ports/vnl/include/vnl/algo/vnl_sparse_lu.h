// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_sparse_lu.h: P A = L U for a square vnl_sparse_matrix, kept
/// sparse, to solve A x = b and A^T x = b and give det A. Ours: row-wise Gaussian elimination
/// with threshold pivoting (among the rows whose pivot is at least pivot_thresh times the
/// column's largest, the one with fewest entries; a diagonal candidate first when diagonal
/// pivoting is on), factored on first use (upstream: Kundert's Sparse 1.3). With
/// estimate_condition, rcond() is 1 / (|A|_inf |A^-1|_inf), computed exactly, and
/// max_error_bound() is n epsilon max|U| / rcond, a bound on the relative error of a solution
/// (upstream: Sparse's own roundoff estimate, so other numbers).
#pragma once

#ifdef vnl_sparse_lu_h_
#error "edgetrack's drop-in vnl/algo/vnl_sparse_lu.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <map>
#include <vector>

#include "vnl/vnl_sparse_matrix.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

class vnl_sparse_lu {
 public:
  enum operation { quiet, verbose, estimate_condition, estimate_condition_verbose };

  explicit vnl_sparse_lu(const vnl_sparse_matrix<double>& M, operation mode = quiet);

  void set_pivot_thresh(double pivot_thresh) { pivot_thresh_ = pivot_thresh; }
  void set_absolute_thresh(double absolute_thresh) { absolute_thresh_ = absolute_thresh; }
  void set_diagonal_pivoting(int diag_pivoting) { diag_pivoting_ = diag_pivoting; }

  vnl_vector<double> solve(const vnl_vector<double>& b);
  void solve(const vnl_vector<double>& b, vnl_vector<double>* x);
  vnl_vector<double> solve_transpose(const vnl_vector<double>& b);
  void solve_transpose(const vnl_vector<double>& b, vnl_vector<double>* x);
  double determinant();
  /// 0 unless constructed with estimate_condition(_verbose).
  double rcond();
  double max_error_bound();

 protected:
  void decompose_matrix();
  bool est_condition();

  vnl_sparse_matrix<double> A_;
  bool factored_ = false;
  bool condition_computed_ = false;
  operation mode_;
  double pivot_thresh_ = 0.1;
  double absolute_thresh_ = 0;
  int diag_pivoting_ = 1;
  double rcond_ = 0;
  double largest_ = 0;
  int sign_ = 1;
  bool singular_ = false;
  std::vector<unsigned> perm_;                 ///< row k of L U is row perm_[k] of A
  std::vector<std::map<unsigned, double>> L_;  ///< strictly lower part, unit diagonal implied
  std::vector<std::map<unsigned, double>> U_;  ///< upper part with the diagonal
};

}  // inline namespace edgetrack_ports
