// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_vector for float (upstream: core/vnl/Templates/).
#include "vnl/vnl_vector.hxx"

inline namespace edgetrack_ports {

VNL_VECTOR_INSTANTIATE(float);
/// cos_angle() and angle() need a floating-point square root and acos: only float and double have them compiled in.
template float cos_angle(const vnl_vector<float>&, const vnl_vector<float>&);
template double angle(const vnl_vector<float>&, const vnl_vector<float>&);

}  // inline namespace edgetrack_ports
