// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_quaternion for double (upstream: core/vnl/Templates/).
#include "vnl/vnl_quaternion.hxx"

inline namespace edgetrack_ports {

VNL_QUATERNION_INSTANTIATE(double);

}  // inline namespace edgetrack_ports
