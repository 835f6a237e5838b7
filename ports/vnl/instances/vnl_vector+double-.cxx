// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_vector for double (upstream: core/vnl/Templates/).
#include "vnl/vnl_vector.hxx"

inline namespace edgetrack_ports {

VNL_VECTOR_INSTANTIATE(double);
/// cos_angle() and angle() need a floating-point square root and acos: only float and double have them compiled in.
template double cos_angle(const vnl_vector<double>&, const vnl_vector<double>&);
template double angle(const vnl_vector<double>&, const vnl_vector<double>&);

}  // inline namespace edgetrack_ports
