// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_sparse_lst_sqr_function_of for double (upstream's only scalar).
#include "vnl/vnl_sparse_lst_sqr_function.hxx"

inline namespace edgetrack_ports {

VNL_SPARSE_LST_SQR_FUNCTION_INSTANTIATE(double);

}  // inline namespace edgetrack_ports
