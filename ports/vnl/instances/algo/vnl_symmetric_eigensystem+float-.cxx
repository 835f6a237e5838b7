// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_symmetric_eigensystem for float (upstream: core/vnl/algo/Templates/).
#include "vnl/algo/vnl_symmetric_eigensystem.hxx"

inline namespace edgetrack_ports {

VNL_SYMMETRIC_EIGENSYSTEM_INSTANTIATE(float);

}  // inline namespace edgetrack_ports
