// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_sparse_lst_sqr_function_of for the configured `real` when it is not double
/// (the double file covers that case).
#include "real/real.h"
#include "vnl/vnl_sparse_lst_sqr_function.hxx"

#if !defined(EDGETRACK_REAL_DOUBLE)
inline namespace edgetrack_ports {

VNL_SPARSE_LST_SQR_FUNCTION_INSTANTIATE(real);
}  // inline namespace edgetrack_ports
#endif
