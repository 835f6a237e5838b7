// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/algo/vnl_gaussian_kernel_1d.h"

#include <cmath>

inline namespace edgetrack_ports {

namespace {
/// The x where the normalised density 1 / (sigma sqrt(2 pi)) exp(-x^2 / 2 sigma^2) is cutoff.
double width_at(double sigma, double cutoff) {
  const double sqrt_two_pi = std::sqrt(2 * std::acos(-1.0));
  return sigma * std::sqrt(-2 * std::log(cutoff * sigma * sqrt_two_pi));
}
}  // namespace

vnl_gaussian_kernel_1d::vnl_gaussian_kernel_1d(double sigma, double cutoff)
    : vec_(static_cast<unsigned>(std::ceil(width_at(sigma, cutoff)))), inscale_(0.5 / (sigma * sigma)) {
  double area = 0;
  for (unsigned i = 0; i < vec_.size(); ++i) area += vec_[i] = G(i);
  vec_ *= 0.5 / area;
}

double vnl_gaussian_kernel_1d::G(double x) const { return std::exp(-x * x * inscale_); }

}  // inline namespace edgetrack_ports
