// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_definite_integral.h: the base of the definite integrators, which
/// holds the integrand set with set_fnct. Upstream keeps it in a static member shared by all
/// integrators; ours is per integrator (no shared mutable state), which callers cannot tell
/// apart unless they relied on one integrator seeing another's integrand.
#pragma once

#ifdef VNL_DEFINITE_INTEGRAL_H_
#error "edgetrack's drop-in vnl/vnl_definite_integral.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_integrant_fnct.h"

inline namespace edgetrack_ports {

class vnl_definite_integral {
 public:
  vnl_definite_integral() = default;
  virtual ~vnl_definite_integral() = default;
  void set_fnct(vnl_integrant_fnct* f) { pfnct_ = f; }

 protected:
  vnl_integrant_fnct* pfnct_ = nullptr;
};

}  // inline namespace edgetrack_ports
