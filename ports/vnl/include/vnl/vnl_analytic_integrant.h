// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_analytic_integrant.h: an integrand given in closed form.
#pragma once

#ifdef VNL_ANALYTIC_INTEGRANT_
#error "edgetrack's drop-in vnl/vnl_analytic_integrant.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_integrant_fnct.h"

inline namespace edgetrack_ports {

class vnl_analytic_integrant : public vnl_integrant_fnct {
 public:
  vnl_analytic_integrant() = default;
  ~vnl_analytic_integrant() override = default;
  double f_(double x) override = 0;
};

}  // inline namespace edgetrack_ports
