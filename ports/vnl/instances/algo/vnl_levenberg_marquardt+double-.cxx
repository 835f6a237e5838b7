// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_levenberg_marquardt_of for double, upstream's scalar, with its one-call form.
#include "vnl/algo/vnl_levenberg_marquardt.hxx"

inline namespace edgetrack_ports {

VNL_LEVENBERG_MARQUARDT_INSTANTIATE(double);

vnl_vector<double> vnl_levenberg_marquardt_minimize(vnl_least_squares_function& f,
                                                    const vnl_vector<double>& initial_estimate) {
  vnl_vector<double> x = initial_estimate;
  vnl_levenberg_marquardt lm(f);
  lm.minimize(x);
  return x;
}

}  // inline namespace edgetrack_ports
