// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_symmetric_eigensystem for float (upstream: core/vnl/algo/Templates/).
#include "vnl/algo/vnl_symmetric_eigensystem.hxx"

VNL_SYMMETRIC_EIGENSYSTEM_INSTANTIATE(float);
