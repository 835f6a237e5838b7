// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_quaternion for double (upstream: core/vnl/Templates/).
#include "vnl/vnl_quaternion.hxx"

VNL_QUATERNION_INSTANTIATE(double);
