// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/algo/vnl_lsqr.h"

#include <cmath>
#include <ostream>

inline namespace edgetrack_ports {

int vnl_lsqr::minimize(vnl_vector<double>& x) {
  const unsigned m = ls_->get_number_of_residuals(), n = ls_->get_number_of_unknowns();
  x.set_size(n);
  x.fill(0);
  vnl_vector<double> u(m), v(n), w(n), Av(m), Atu(n);
  ls_->get_rhs(u);
  // Golub-Kahan bidiagonalisation from beta u = b, alpha v = A^T u.
  double beta = u.two_norm();
  if (beta > 0) u /= beta;
  ls_->transpose_multiply(u, v);
  double alpha = v.two_norm();
  if (alpha > 0) v /= alpha;
  w = v;
  double phibar = beta, rhobar = alpha, anorm = 0, ddnorm = 0;
  const double bnorm = beta;
  num_iter_ = 0;
  return_code_ = 0;
  resid_norm_estimate_ = beta;
  if (alpha * beta == 0) return 0;  // x = 0 solves it (in the least-squares sense)
  while (return_code_ == 0) {
    ++num_iter_;
    ls_->multiply(v, Av);
    u = Av - alpha * u;
    beta = u.two_norm();
    if (beta > 0) u /= beta;
    anorm = std::sqrt(anorm * anorm + alpha * alpha + beta * beta);
    ls_->transpose_multiply(u, Atu);
    v = Atu - beta * v;
    alpha = v.two_norm();
    if (alpha > 0) v /= alpha;
    // Eliminate beta by a plane rotation of the lower bidiagonal system.
    const double rho = std::sqrt(rhobar * rhobar + beta * beta);
    const double c = rhobar / rho, s = beta / rho;
    const double theta = s * alpha;
    rhobar = -c * alpha;
    const double phi = c * phibar;
    phibar = s * phibar;
    ddnorm += (w / rho).squared_magnitude();
    x += (phi / rho) * w;
    w = v - (theta / rho) * w;
    // The stopping tests with zero tolerances: machine precision, conditioning, iterations.
    const double xnorm = x.two_norm(), acond = anorm * std::sqrt(ddnorm);
    const double rnorm = phibar, arnorm = alpha * std::fabs(c) * phibar;
    const double test1 = rnorm / bnorm, test2 = rnorm > 0 ? arnorm / (anorm * rnorm) : 0, test3 = 1 / acond;
    const double scaled_test1 = test1 / (1 + anorm * xnorm / bnorm);
    resid_norm_estimate_ = rnorm;
    result_norm_estimate_ = xnorm;
    A_condition_estimate_ = acond;
    if (num_iter_ >= max_iter_) return_code_ = 7;
    if (1 + test3 <= 1) return_code_ = 6;
    if (1 + test2 <= 1) return_code_ = 5;
    if (1 + scaled_test1 <= 1) return_code_ = 4;
    if (test2 <= 0) return_code_ = 2;
    if (test1 <= 0) return_code_ = 1;
  }
  return static_cast<int>(return_code_);
}

void vnl_lsqr::diagnose_outcome(std::ostream& os) const {
  translate_return_code(os, static_cast<int>(return_code_));
  os << "vnl_lsqr: residual norm estimate = " << resid_norm_estimate_
     << "\nvnl_lsqr: result norm estimate   = " << result_norm_estimate_
     << "\nvnl_lsqr: condition no. estimate = " << A_condition_estimate_
     << "\nvnl_lsqr: iterations             = " << num_iter_ << '\n';
}

void vnl_lsqr::translate_return_code(std::ostream& os, int rc) {
  static const char* const kReasons[] = {
      "x = 0 is the exact solution. No iterations were performed.",
      "The equations A*x = b are probably compatible: |A*x - b| is small enough for the tolerances.",
      "The system A*x = b is probably not compatible: a least-squares solution within the tolerances.",
      "An estimate of cond(A) has exceeded its limit: the system appears ill-conditioned.",
      "The equations A*x = b are probably compatible: |A*x - b| is as small as this machine allows.",
      "The system A*x = b is probably not compatible: a least-squares solution as accurate as this "
      "machine allows.",
      "cond(A) is too large for further iterations at this machine's precision.",
      "The iteration limit was reached."};
  if (rc < 0 || rc > 7)
    os << "vnl_lsqr: Illegal return code : " << rc << '\n';
  else
    os << "vnl_lsqr: " << kReasons[rc] << '\n';
}

}  // inline namespace edgetrack_ports
