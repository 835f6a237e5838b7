// SPDX-License-Identifier: BSD-3-Clause
/// Our MINPACK instantiated for double, whatever `real` this host tree is configured with.
#include "netlib/minpack.hxx"

NETLIB_MINPACK_INSTANTIATE(double)
