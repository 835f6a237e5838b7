// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_adaptsimpson_integral.h: adaptive Simpson integration,
/// halving each interval until its two halves agree with the whole to the accuracy (with
/// Richardson's correction), down to `depth` levels.
#pragma once

#ifdef VNL_ADAPTSIMPSON_INTEGRAL_H_
#error "edgetrack's drop-in vnl/algo/vnl_adaptsimpson_integral.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_definite_integral.h"
#include "vnl/vnl_integrant_fnct.h"

inline namespace edgetrack_ports {

class vnl_adaptsimpson_integral : public vnl_definite_integral {
 public:
  explicit vnl_adaptsimpson_integral(int depth = 32) : depth_(depth) {}
  double integral(vnl_integrant_fnct* f, double a, double b, double accuracy);

 protected:
  double adaptivesimpson(double a, double b, double fa, double fm, double fb, double whole, double eps, int level);
  int depth_;
};

}  // inline namespace edgetrack_ports
