// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_gaussian_kernel_1d.h: one half (x = 0, 1, 2 ...) of a sampled
/// Gaussian of standard deviation sigma, out to where the normalised density falls below
/// cutoff, scaled so that the half sums to 0.5. G(x) = exp(-x^2 / 2 sigma^2), unnormalised.
#pragma once

#ifdef vnl_gaussian_kernel_1d_h_
#error "edgetrack's drop-in vnl/algo/vnl_gaussian_kernel_1d.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

class vnl_gaussian_kernel_1d {
 public:
  explicit vnl_gaussian_kernel_1d(double sigma, double cutoff = 0.5 / 256.0);
  double G(double x) const;
  int width() const { return static_cast<int>(vec_.size()); }
  double operator[](int i) const { return vec_[static_cast<unsigned>(i)]; }

 protected:
  vnl_vector<double> vec_;
  double inscale_;
};

}  // inline namespace edgetrack_ports
