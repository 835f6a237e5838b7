// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_integrant_fnct.h: the function f(x) an integrator integrates.
#pragma once

#ifdef VNL_INTEGRANT_FNCT_H_
#error "edgetrack's drop-in vnl/vnl_integrant_fnct.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

inline namespace edgetrack_ports {

class vnl_integrant_fnct {
 public:
  vnl_integrant_fnct() = default;
  virtual ~vnl_integrant_fnct() = default;
  virtual double f_(double x) = 0;
};

}  // inline namespace edgetrack_ports
