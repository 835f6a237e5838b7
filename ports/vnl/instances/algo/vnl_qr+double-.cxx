// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_qr for double (upstream: core/vnl/algo/Templates/).
#include "vnl/algo/vnl_qr.hxx"

inline namespace edgetrack_ports {

VNL_QR_INSTANTIATE(double);

}  // inline namespace edgetrack_ports
