// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_cholesky for double (upstream: core/vnl/algo/Templates/).
#include "vnl/algo/vnl_cholesky.hxx"

VNL_CHOLESKY_INSTANTIATE(double);
