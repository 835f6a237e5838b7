// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_qr for float (upstream: core/vnl/algo/Templates/).
#include "vnl/algo/vnl_qr.hxx"

inline namespace edgetrack_ports {

VNL_QR_INSTANTIATE(float);

}  // inline namespace edgetrack_ports
