// SPDX-License-Identifier: BSD-3-Clause
/// Definitions for vnl_levenberg_marquardt.h. Include it only to instantiate the minimiser for
/// a scalar that the library does not instantiate.
#pragma once

#include <cmath>
#include <iostream>

#include "netlib/minpack.hxx"
#include "vnl/algo/vnl_levenberg_marquardt.h"
#include "vnl/vnl_least_squares_function.hxx"

inline namespace edgetrack_ports {

template <class T>
vnl_levenberg_marquardt_of<T>::vnl_levenberg_marquardt_of(vnl_least_squares_function_of<T>& f) : f_(&f) {
  this->maxfev = 400 * static_cast<int>(f.get_number_of_unknowns());
}

template <class T>
bool vnl_levenberg_marquardt_of<T>::minimize(vnl_vector<T>& x) {
  return f_->has_gradient() ? minimize_using_gradient(x) : minimize_without_gradient(x);
}

template <class T>
bool vnl_levenberg_marquardt_of<T>::input_is_valid(const vnl_vector<T>& x) {
  const unsigned m = f_->get_number_of_residuals();
  const unsigned n = f_->get_number_of_unknowns();
  if (m < n || x.size() != n) {
    if (this->verbose_) {
      std::cerr << "vnl_levenberg_marquardt: " << n << " unknowns, " << m << " residuals, x of size " << x.size()
                << '\n';
    }
    this->failure_code_ = this->ERROR_DODGY_INPUT;
    return false;
  }
  return true;
}

template <class T>
bool vnl_levenberg_marquardt_of<T>::outcome_is_success() const {
  return this->failure_code_ >= this->CONVERGED_FTOL && this->failure_code_ <= this->CONVERGED_GTOL;
}

template <class T>
void vnl_levenberg_marquardt_of<T>::prepare_buffers(int m, int n) {
  fdjac_.set_size(n, m);
  ipvt_.set_size(n);
  x_buffer_.set_size(n);
  fx_buffer_.set_size(m);
  jacobian_buffer_.set_size(m, n);
}

template <class T>
int vnl_levenberg_marquardt_of<T>::lmder_callback(void* self_pointer, int m, int n, const T* x, T* fx, T* fjac,
                                                  int ldfjac, int iflag) {
  auto* self = static_cast<vnl_levenberg_marquardt_of*>(self_pointer);
  vnl_least_squares_function_of<T>* f = self->f_;
  vnl_vector<T>& xv = self->x_buffer_;
  vnl_vector<T>& fxv = self->fx_buffer_;
  xv.copy_in(x);
  if (iflag == 0) {
    if (self->trace) f->trace(self->num_iterations_, xv, fxv.copy_in(fx));
  } else if (iflag == 1) {
    f->f(xv, fxv);
    fxv.copy_out(fx);
    if (self->num_iterations_ == 0) self->start_error_ = fxv.rms();
    ++self->num_iterations_;
  } else {
    vnl_matrix<T>& jacobian = self->jacobian_buffer_;
    f->gradf(xv, jacobian);
    if (self->check_derivatives_ > 0) self->check_jacobian(xv, jacobian);
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < m; ++i) fjac[i + j * ldfjac] = jacobian(i, j);
    }
  }
  if (f->failure) {
    f->clear_failure();
    return -1;
  }
  return iflag;
}

template <class T>
int vnl_levenberg_marquardt_of<T>::lmdif_callback(void* self_pointer, int, int, const T* x, T* fx, int iflag) {
  auto* self = static_cast<vnl_levenberg_marquardt_of*>(self_pointer);
  vnl_least_squares_function_of<T>* f = self->f_;
  vnl_vector<T>& xv = self->x_buffer_;
  vnl_vector<T>& fxv = self->fx_buffer_;
  xv.copy_in(x);
  if (iflag == 0) {
    if (self->trace) f->trace(self->num_iterations_, xv, fxv.copy_in(fx));
    ++self->num_iterations_;
  } else {
    f->f(xv, fxv);
    fxv.copy_out(fx);
    if (!self->start_error_set_) {
      self->start_error_ = fxv.rms();
      self->start_error_set_ = true;
    }
  }
  if (f->failure) {
    f->clear_failure();
    return -1;
  }
  return iflag;
}

template <class T>
bool vnl_levenberg_marquardt_of<T>::minimize_using_gradient(vnl_vector<T>& x) {
  if (!f_->has_gradient()) {
    if (this->verbose_) std::cerr << "vnl_levenberg_marquardt: minimize_using_gradient on a function without one\n";
    this->failure_code_ = this->ERROR_DODGY_INPUT;
    return false;
  }
  if (!input_is_valid(x)) return false;
  const int m = static_cast<int>(f_->get_number_of_residuals());
  const int n = static_cast<int>(f_->get_number_of_unknowns());
  vnl_vector<T> fx(m), diag(n), qtf(n), wa1(n), wa2(n), wa3(n), wa4(m);
  prepare_buffers(m, n);
  this->num_iterations_ = 0;
  this->start_error_ = T(0);
  int nfev = 0;
  const int info = netlib::lmder<T>(&lmder_callback, this, m, n, x.data_block(), fx.data_block(), fdjac_.data_block(),
                                    m, this->ftol, this->xtol, this->gtol, this->maxfev, diag.data_block(), 1, T(100),
                                    1, &nfev, &num_jacobian_evaluations_, ipvt_.data_block(), qtf.data_block(),
                                    wa1.data_block(), wa2.data_block(), wa3.data_block(), wa4.data_block());
  this->num_evaluations_ = this->num_iterations_;  // as upstream: for lmder they are the same
  this->failure_code_ = info < 0 ? this->ERROR_FAILURE : static_cast<ReturnCodes>(info);
  this->end_error_ = fx.rms();
  return outcome_is_success();
}

template <class T>
bool vnl_levenberg_marquardt_of<T>::minimize_without_gradient(vnl_vector<T>& x) {
  if (!input_is_valid(x)) return false;
  const int m = static_cast<int>(f_->get_number_of_residuals());
  const int n = static_cast<int>(f_->get_number_of_unknowns());
  vnl_vector<T> fx(m), diag(n), qtf(n), wa1(n), wa2(n), wa3(n), wa4(m);
  prepare_buffers(m, n);
  this->num_iterations_ = 0;
  num_jacobian_evaluations_ = 0;
  start_error_set_ = false;
  int nfev = 0;
  const int info = netlib::lmdif<T>(&lmdif_callback, this, m, n, x.data_block(), fx.data_block(), this->ftol,
                                    this->xtol, this->gtol, this->maxfev, this->epsfcn, diag.data_block(), 1, T(100), 1,
                                    &nfev, fdjac_.data_block(), m, ipvt_.data_block(), qtf.data_block(),
                                    wa1.data_block(), wa2.data_block(), wa3.data_block(), wa4.data_block());
  this->num_evaluations_ = nfev;
  this->failure_code_ = info < 0 ? this->ERROR_FAILURE : static_cast<ReturnCodes>(info);
  this->end_error_ = fx.rms();
  return outcome_is_success();
}

template <class T>
void vnl_levenberg_marquardt_of<T>::diagnose_outcome() const {
  diagnose_outcome(std::cerr);
}

template <class T>
void vnl_levenberg_marquardt_of<T>::diagnose_outcome(std::ostream& s) const {
  const char* what = "unknown info code from lmder";
  switch (this->failure_code_) {
    case vnl_nonlinear_minimizer_of<T>::ERROR_FAILURE:
      what = "failure in the least-squares function";
      break;
    case vnl_nonlinear_minimizer_of<T>::ERROR_DODGY_INPUT:
      what = "dodgy input";
      break;
    case vnl_nonlinear_minimizer_of<T>::CONVERGED_FTOL:
      what = "converged to ftol";
      break;
    case vnl_nonlinear_minimizer_of<T>::CONVERGED_XTOL:
      what = "converged to xtol";
      break;
    case vnl_nonlinear_minimizer_of<T>::CONVERGED_XFTOL:
      what = "converged nicely";
      break;
    case vnl_nonlinear_minimizer_of<T>::CONVERGED_GTOL:
      what = "converged via gtol";
      break;
    case vnl_nonlinear_minimizer_of<T>::TOO_MANY_ITERATIONS:
      what = "too many iterations";
      break;
    case vnl_nonlinear_minimizer_of<T>::FAILED_FTOL_TOO_SMALL:
      what = "ftol is too small; no further reduction of the sum of squares is possible";
      break;
    case vnl_nonlinear_minimizer_of<T>::FAILED_XTOL_TOO_SMALL:
      what = "xtol is too small; no further improvement of x is possible";
      break;
    case vnl_nonlinear_minimizer_of<T>::FAILED_GTOL_TOO_SMALL:
      what = "gtol is too small; fx is orthogonal to the Jacobian to machine precision";
      break;
    default:
      break;
  }
  s << "vnl_levenberg_marquardt: " << what << "\nvnl_levenberg_marquardt: " << this->num_iterations_ << " iterations, "
    << this->num_evaluations_ << " evaluations, " << f_->get_number_of_residuals()
    << " residuals.  RMS error start/end " << static_cast<double>(this->start_error_) << '/'
    << static_cast<double>(this->end_error_) << '\n';
}

template <class T>
void vnl_levenberg_marquardt_of<T>::check_jacobian(const vnl_vector<T>& x, const vnl_matrix<T>& jacobian) {
  --this->check_derivatives_;
  vnl_matrix<T> differences(jacobian.rows(), jacobian.cols());
  using std::sqrt;
  f_->ffdgradf(x, differences, sqrt(this->epsfcn));
  for (unsigned j = 0; j < jacobian.cols(); ++j) {
    for (unsigned i = 0; i < jacobian.rows(); ++i) {
      const T gap = jacobian(i, j) - differences(i, j);
      if (gap * gap > this->epsfcn) {
        std::cout << "Jac(" << j << ", " << i << ") diff: " << jacobian(i, j) << "  " << differences(i, j) << "  "
                  << gap << '\n';
      }
    }
  }
}

template <class T>
const vnl_matrix<T>& vnl_levenberg_marquardt_of<T>::get_JtJ() {
  // fdjac_ holds R in the upper triangle of MINPACK's column-major array: R(i, j) = fdjac_(j, i).
  const std::size_t n = fdjac_.rows();
  vnl_matrix<T> r(n, n);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i; j < n; ++j) r(i, j) = fdjac_(j, i);
  }
  const vnl_matrix<T> rtr = r.transpose() * r;
  // Column j of the Jacobian was moved to position k with ipvt_[k] == j.
  jtj_.set_size(n, n);
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = 0; b < n; ++b) jtj_(ipvt_[a], ipvt_[b]) = rtr(a, b);
  }
  return jtj_;
}

#define VNL_LEVENBERG_MARQUARDT_INSTANTIATE(T) template class vnl_levenberg_marquardt_of<T>

}  // inline namespace edgetrack_ports
