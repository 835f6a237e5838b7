// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_svd for float (upstream: core/vnl/algo/Templates/).
#include "vnl/algo/vnl_svd.hxx"

VNL_SVD_INSTANTIATE(float);
