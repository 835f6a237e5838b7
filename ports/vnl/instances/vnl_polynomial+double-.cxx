// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_polynomial for double (upstream: core/vnl/Templates/).
#include "vnl/vnl_polynomial.hxx"

VNL_POLYNOMIAL_INSTANTIATE(double);
