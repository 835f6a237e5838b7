// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_integrant_fnct.h: the function f(x) an integrator integrates.
#pragma once

class vnl_integrant_fnct {
 public:
  vnl_integrant_fnct() = default;
  virtual ~vnl_integrant_fnct() = default;
  virtual double f_(double x) = 0;
};
