// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_rnpoly_solve.h: every finite solution of a square system of
/// real polynomial equations in n unknowns (n polynomials in n variables), by homotopy
/// continuation from the total-degree start system x_i^(d_i) = 1 (Bezout's number of paths),
/// tracked in complex arithmetic with Euler prediction and Newton correction; paths that
/// diverge (solutions at infinity) are dropped. real() and imag() give each solution's real and
/// imaginary parts, realroots(tol) those whose imaginary part has norm below tol. The vectors
/// belong to the solver (as upstream, raw pointers; valid while it lives). Ours is our own
/// tracker (upstream: a port of a Fortran homotopy code); a real solution's imaginary part is
/// exactly 0 once Newton's method in real arithmetic converges from its real part.
#pragma once

#ifdef vnl_rnpoly_solve_h_
#error "edgetrack's drop-in vnl/algo/vnl_rnpoly_solve.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <memory>
#include <vector>

#include "vnl/vnl_real_npolynomial.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

class vnl_rnpoly_solve {
 public:
  explicit vnl_rnpoly_solve(std::vector<vnl_real_npolynomial*> ps) : ps_(std::move(ps)) { compute(); }
  vnl_rnpoly_solve(const vnl_rnpoly_solve&) = delete;
  vnl_rnpoly_solve& operator=(const vnl_rnpoly_solve&) = delete;

  std::vector<vnl_vector<double>*> real() { return r_; }
  std::vector<vnl_vector<double>*> imag() { return i_; }
  std::vector<vnl_vector<double>*> realroots(double tol = 1e-12);

 private:
  bool compute();

  std::vector<vnl_real_npolynomial*> ps_;
  std::vector<vnl_vector<double>*> r_;
  std::vector<vnl_vector<double>*> i_;
  std::vector<std::unique_ptr<vnl_vector<double>>> storage_;
};

}  // inline namespace edgetrack_ports
