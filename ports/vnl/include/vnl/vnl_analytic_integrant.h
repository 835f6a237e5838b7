// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_analytic_integrant.h: an integrand given in closed form.
#pragma once

#include "vnl/vnl_integrant_fnct.h"

class vnl_analytic_integrant : public vnl_integrant_fnct {
 public:
  vnl_analytic_integrant() = default;
  ~vnl_analytic_integrant() override = default;
  double f_(double x) override = 0;
};
