// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates our MINPACK routines for the configured `real`.
#include "netlib/minpack.hxx"
#include "real/real.h"

NETLIB_MINPACK_INSTANTIATE(real)
