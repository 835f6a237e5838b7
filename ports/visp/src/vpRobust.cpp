// SPDX-License-Identifier: BSD-3-Clause
/// vpRobust::MEstimator. The medians are order statistics (std::nth_element): the same values
/// as upstream's quick-select, whatever order it leaves the elements in.
#include "visp3/core/vpRobust.h"

#include <algorithm>
#include <cmath>

inline namespace edgetrack_ports {

namespace {
/// The k-th smallest of `values` (reordered).
real kth_smallest(std::vector<real>& values, unsigned int k) {
  std::nth_element(values.begin(), values.begin() + k, values.end());
  return values[k];
}
}  // namespace

void vpRobust::MEstimator(vpRobustEstimatorType method, const vpColVector& residues, vpColVector& weights) {
  using std::abs;
  const unsigned int n = residues.getRows();
  weights.resize(n, false);
  if (n == 0) return;
  const unsigned int median_index = (n + 1) / 2 - 1;  // ceil(n / 2) - 1
  sorted_.assign(residues.data(), residues.data() + n);
  const real median = kth_smallest(sorted_, median_index);
  normres_.resize(n);
  for (unsigned int k = 0; k < n; ++k) normres_[k] = abs(residues[k] - median);
  sorted_.assign(normres_.begin(), normres_.end());
  mad_ = real(1.4826) * kth_smallest(sorted_, median_index);
  if (mad_ < mad_min_) mad_ = mad_min_;

  for (unsigned int k = 0; k < n; ++k) {
    const real x = normres_[k];
    switch (method) {
      case TUKEY: {
        const real scaled = x / (mad_ * real(4.6851));
        const real q = scaled * scaled;
        weights[k] = q > 1 ? real(0) : (real(1) - q) * (real(1) - q);
        break;
      }
      case CAUCHY: {
        const real scaled = x / (mad_ * real(2.3849));
        weights[k] = real(1) / (real(1) + scaled * scaled);
        break;
      }
      case HUBER: {
        const real scaled = x / (mad_ * real(1.345));
        weights[k] = scaled <= 1 ? real(1) : real(1) / scaled;
        break;
      }
    }
  }
}

}  // inline namespace edgetrack_ports
