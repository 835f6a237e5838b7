// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_simpson_integral.h: composite Simpson's rule with n
/// intervals (rounded up to even) over [a, b]; upstream calls netlib's simpson.
#pragma once

#ifdef VNL_SIMPSON_INTEGRAL_H_
#error "edgetrack's drop-in vnl/algo/vnl_simpson_integral.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_definite_integral.h"
#include "vnl/vnl_integrant_fnct.h"

inline namespace edgetrack_ports {

class vnl_simpson_integral : public vnl_definite_integral {
 public:
  vnl_simpson_integral() = default;
  double integral(vnl_integrant_fnct* f, double a, double b, long n);
};

}  // inline namespace edgetrack_ports
