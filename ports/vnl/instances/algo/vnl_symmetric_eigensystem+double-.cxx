// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_symmetric_eigensystem for double (upstream: core/vnl/algo/Templates/).
#include "vnl/algo/vnl_symmetric_eigensystem.hxx"

inline namespace edgetrack_ports {

VNL_SYMMETRIC_EIGENSYSTEM_INSTANTIATE(double);

}  // inline namespace edgetrack_ports
