// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_lsqr.h: Paige and Saunders' LSQR for the least-squares
/// solution of a (typically sparse) vnl_linear_system A x = b, through A x and A^T y only; no
/// damping, zero tolerances (so it runs to the machine's precision) and at most 4 n iterations
/// by default, as upstream. minimize(x) returns LSQR's stopping reason (translate_return_code
/// names them): 0 x = 0 solves it, 1/2 within the tolerances, 4/5 at machine precision, 6
/// ill-conditioned, 7 the iteration limit.
#pragma once

#ifdef vnl_lsqr_h_
#error "edgetrack's drop-in vnl/algo/vnl_lsqr.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <iosfwd>

#include "vnl/vnl_linear_system.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

class vnl_lsqr {
 public:
  explicit vnl_lsqr(vnl_linear_system& ls) : ls_(&ls), max_iter_(4 * static_cast<long>(ls.get_number_of_unknowns())) {}
  void set_max_iterations(long max_iter) { max_iter_ = max_iter; }
  /// Solves from x = 0, leaving the solution in x (sized to the unknowns).
  int minimize(vnl_vector<double>& x);
  long get_number_of_iterations() const { return num_iter_; }
  void diagnose_outcome(std::ostream& os) const;
  static void translate_return_code(std::ostream& os, int return_code);
  /// |b - A x| at the end, as LSQR estimates it.
  double get_resid_norm_estimate() const { return resid_norm_estimate_; }
  long return_code() const { return return_code_; }

 protected:
  vnl_linear_system* ls_;
  long max_iter_;
  long num_iter_ = 0;
  double resid_norm_estimate_ = 0;
  double result_norm_estimate_ = 0;
  double A_condition_estimate_ = 0;
  long return_code_ = 0;
};

}  // inline namespace edgetrack_ports
