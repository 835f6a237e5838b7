// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors ViSP's visp3/core/vpRobust.h: M-estimator weights from residues, with the scale
/// taken as 1.4826 times the median absolute deviation from the median (at least the set minimum).
/// The line and ellipse trackers use TUKEY. The buffers are members and keep their capacity.
#pragma once

#ifdef vpRobust_h
#error "edgetrack's drop-in visp3/core/vpRobust.h and ViSP's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <vector>

#include "real/real.h"
#include "visp3/core/vpColVector.h"

inline namespace edgetrack_ports {

class vpRobust {
 public:
  typedef enum { TUKEY, CAUCHY, HUBER } vpRobustEstimatorType;

  vpRobust() = default;

  /// Weights in [0, 1] for `residues`: with med the median (upstream's: the ceil(n/2)-th smallest)
  /// and sigma = max(1.4826 * median |r - med|, min MAD), the weight of r is Tukey's
  /// (1 - (|r - med| / (4.6851 sigma))^2)^2 (0 beyond), Cauchy's 1 / (1 + (|r - med| / (2.3849 sigma))^2)
  /// or Huber's min(1, 1.345 sigma / |r - med|).
  void MEstimator(vpRobustEstimatorType method, const vpColVector& residues, vpColVector& weights);

  real getMedianAbsoluteDeviation() const { return mad_; }
  real getMinMedianAbsoluteDeviation() const { return mad_min_; }
  void setMinMedianAbsoluteDeviation(real mad_min) { mad_min_ = mad_min; }
#if defined(EDGETRACK_REAL_S47_16) || defined(EDGETRACK_REAL_S40_23)
  void setMinMedianAbsoluteDeviation(double mad_min) { mad_min_ = real(mad_min); }
#endif

 private:
  real mad_ = 0;
  real mad_min_ = real(0.0017);
  std::vector<real> sorted_;
  std::vector<real> normres_;
};

}  // inline namespace edgetrack_ports
